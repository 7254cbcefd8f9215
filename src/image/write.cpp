#include "image/write.h"

#include <stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "image/exr_layers.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// Encoders write to memory and atomic_file does the I/O: neither stb nor tinyexr reports why
// a file write failed, while our own write() reports errno (disk full, permission denied).
// stb's write callback: appends to the std::vector<unsigned char> in context.
void append(void* context, void* data, int size) {
    auto* bytes = static_cast<unsigned char*>(data);
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    out->insert(out->end(), bytes, bytes + size);
}

std::vector<unsigned char> encodePngRgb8(int width, int height, const std::vector<std::uint8_t>& rgb) {
    std::vector<unsigned char> out;
    if (!stbi_write_png_to_func(append, &out, width, height, 3, rgb.data(), width * 3)) {
        throw Error("PNG encoding failed");
    }
    return out;
}

// The other 8-bit formats stb writes: JPEG, TGA (RLE), BMP.
std::vector<unsigned char> encodeStb8(ImageFormat format, int width, int height, const std::vector<std::uint8_t>& rgb) {
    std::vector<unsigned char> out;
    int ok = 0;
    if (format == ImageFormat::Jpeg) ok = stbi_write_jpg_to_func(append, &out, width, height, 3, rgb.data(), 95);
    else if (format == ImageFormat::Tga) ok = stbi_write_tga_to_func(append, &out, width, height, 3, rgb.data());
    else ok = stbi_write_bmp_to_func(append, &out, width, height, 3, rgb.data());
    if (!ok) throw Error("image encoding failed");
    return out;
}

// Radiance RGBE; negative and non-finite values (none in a render) become 0.
std::vector<unsigned char> encodeHdr(const ImageRgb& image) {
    std::vector<float> rgb(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float v = image.pixels[i][c];
            rgb[3 * i + c] = std::isfinite(v) && v > 0 ? v : 0.0f;
        }
    std::vector<unsigned char> out;
    if (!stbi_write_hdr_to_func(append, &out, image.width, image.height, 3, rgb.data()))
        throw Error("HDR encoding failed");
    return out;
}

std::vector<unsigned char> encodePng(const ImageRgb& image, const ToneMapSettings& settings) {
    return encodePngRgb8(image.width, image.height, toneMapToSrgb8(image, settings));
}

struct MallocFree {
    void operator()(void* p) const { std::free(p); }
};

std::vector<unsigned char> encodeExr(const ImageRgb& image) {
    // EXR readers expect channels sorted by name, so the planes go B, G, R.
    const std::size_t n = image.pixels.size();
    std::vector<float> planes[3];
    for (auto& plane : planes) plane.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        planes[0][i] = image.pixels[i].z;
        planes[1][i] = image.pixels[i].y;
        planes[2][i] = image.pixels[i].x;
    }
    unsigned char* planePtrs[3] = {reinterpret_cast<unsigned char*>(planes[0].data()),
                                   reinterpret_cast<unsigned char*>(planes[1].data()),
                                   reinterpret_cast<unsigned char*>(planes[2].data())};

    EXRImage exr;
    InitEXRImage(&exr);
    exr.num_channels = 3;
    exr.images = planePtrs;
    exr.width = image.width;
    exr.height = image.height;

    EXRChannelInfo channels[3] = {};
    const char* names[3] = {"B", "G", "R"};
    int types[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
    for (int c = 0; c < 3; ++c) {
        std::snprintf(channels[c].name, sizeof channels[c].name, "%s", names[c]);
    }
    EXRHeader header;
    InitEXRHeader(&header);
    header.num_channels = 3;
    header.channels = channels;
    header.pixel_types = types;            // what the planes hold
    header.requested_pixel_types = types;  // what the file stores: float32, so round trips are exact
    header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;  // lossless

    unsigned char* memory = nullptr;
    const char* err = nullptr;
    std::size_t size = SaveEXRImageToMemory(&exr, &header, &memory, &err);
    std::unique_ptr<unsigned char, MallocFree> owned(memory);
    if (size == 0) {
        std::string reason = err ? err : "unknown tinyexr error";
        if (err) FreeEXRErrorMessage(err);
        throw Error("EXR encoding failed: " + reason);
    }
    return std::vector<unsigned char>(memory, memory + size);
}

}  // namespace

ImageFormat formatFromPath(const fs::path& path) {
    std::string ext = lowercase(path.extension().string());
    if (ext == ".png") return ImageFormat::Png;
    if (ext == ".exr") return ImageFormat::Exr;
    if (ext == ".jpg" || ext == ".jpeg") return ImageFormat::Jpeg;
    if (ext == ".tga") return ImageFormat::Tga;
    if (ext == ".bmp") return ImageFormat::Bmp;
    if (ext == ".hdr") return ImageFormat::Hdr;
    throw UsageError("cannot tell the image format of '" + path.string() +
                     "': use a .png or .exr file name (or .jpg, .tga, .bmp, .hdr)");
}

bool isLinearFormat(ImageFormat format) { return format == ImageFormat::Exr || format == ImageFormat::Hdr; }

void writeImage(const fs::path& path, const ImageRgb& image, const ToneMapSettings& settings) {
    PN_CHECK(image.pixels.size() ==
             static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height));
    if (image.empty()) throw Error("cannot write '" + path.string() + "': the image is empty");
    ImageFormat format = formatFromPath(path);
    std::vector<unsigned char> bytes;
    switch (format) {
        case ImageFormat::Png: bytes = encodePng(image, settings); break;
        case ImageFormat::Exr: bytes = encodeExr(image); break;
        case ImageFormat::Hdr: bytes = encodeHdr(image); break;
        default: bytes = encodeStb8(format, image.width, image.height, toneMapToSrgb8(image, settings)); break;
    }
    writeBytesAtomically(path, bytes);
}

ImageRgb readExr(const fs::path& path) {
    // Through OpenEXR (not tinyexr): it reads the multi-layer files `render --aov` writes and
    // every compression, DWA included.
    ExrChannels exr = readExrChannels(path);
    std::vector<std::string> names;
    for (const auto& [name, values] : exr.channels) names.push_back(name);
    const auto rgb = beautyChannels(names);
    if (!rgb) throw Error("cannot read EXR '" + path.string() + "': it has no R, G, B or Y channels");
    ImageRgb image(exr.width, exr.height);
    const std::vector<float>&r = exr.channels.at((*rgb)[0]), &g = exr.channels.at((*rgb)[1]), &b = exr.channels.at((*rgb)[2]);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = {r[i], g[i], b[i]};
    return image;
}

void writePngRgb8(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgb) {
    PN_CHECK(width > 0 && height > 0 && rgb.size() == std::size_t(width) * std::size_t(height) * 3);
    std::vector<unsigned char> bytes = encodePngRgb8(width, height, rgb);
    writeBytesAtomically(path, bytes);
}

}  // namespace penumbra
