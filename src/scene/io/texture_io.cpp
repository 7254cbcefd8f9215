#include "scene/io/texture_io.h"

#include <stb_image.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <fstream>
#include <system_error>

#include "core/error.h"
#include "image/exr_layers.h"
#include "image/tonemap.h"
#include "scene/environment.h"
#include "scene/io/env_load.h"
#include "scene/io/tiff_io.h"

namespace penumbra {
namespace {

// Largest image file read from disk (a 16384^2 PNG is far smaller than this).
constexpr std::uintmax_t kMaxTextureFileBytes = std::uintmax_t(512) << 20;
constexpr double kMaxPixelsPerByte = 8.0 * 1032.0;

bool startsWith(std::string_view bytes, std::string_view magic) {
    return bytes.size() >= magic.size() && std::memcmp(bytes.data(), magic.data(), magic.size()) == 0;
}

void setWhy(std::string* why, std::string text) {
    if (why) *why = std::move(text);
}

constexpr std::string_view kExrMagic{"\x76\x2f\x31\x01", 4};

// Linear light to a texel byte: sRGB-encoded for colour textures, as is for data maps.
std::uint8_t toByte(float linear, bool srgb) {
    if (srgb) return toSrgb8(linear);
    const float v = std::isfinite(linear) ? std::clamp(linear, 0.0f, 1.0f) : 0.0f;
    return std::uint8_t(std::lround(v * 255.0f));
}

Texture makeTexture(const std::string& name, int w, int h, bool srgb) {
    Texture tex;
    tex.name = name;
    tex.width = w;
    tex.height = h;
    tex.srgb = srgb;
    tex.rgba.resize(std::size_t(w) * std::size_t(h) * 4);
    return tex;
}

// A Radiance HDR file as a texture (values above 1 clip: textures are 8-bit).
Texture fromLinear(const EnvironmentMap& map, const std::string& name, bool srgb) {
    Texture tex = makeTexture(name, map.width, map.height, srgb);
    for (std::size_t i = 0; i < map.radiance.size(); ++i) {
        for (int c = 0; c < 3; ++c) tex.rgba[4 * i + std::size_t(c)] = toByte(map.radiance[i][c], srgb);
        tex.rgba[4 * i + 3] = 255;
    }
    return tex;
}

Texture fromTiff(const TiffPixels& tiff, const std::string& name, bool srgb) {
    Texture tex = makeTexture(name, tiff.width, tiff.height, srgb);
    if (!tiff.isFloat) {
        tex.rgba = tiff.rgba8;  // integer TIFFs hold encoded values already
        return tex;
    }
    for (std::size_t i = 0; i < tex.rgba.size(); ++i)
        tex.rgba[i] = i % 4 == 3 ? toByte(tiff.rgbaFloat[i], false) : toByte(tiff.rgbaFloat[i], srgb);
    return tex;
}

// An OpenEXR texture (linear float; alpha from its A channel when it has one).
Texture decodeExrTexture(std::string_view bytes, const std::string& name, bool srgb) {
    const ExrHeaderInfo info = readExrHeader(bytes, name);
    if (info.width <= 0 || info.height <= 0 || info.width > kMaxTextureSide || info.height > kMaxTextureSide)
        throw Error("image is " + std::to_string(info.width) + "x" + std::to_string(info.height) + "; sides must be 1.." +
                    std::to_string(kMaxTextureSide));
    // Decoded as float before it becomes bytes: bounded like an environment map, and by what the
    // file's bytes can hold (as for the other formats).
    if (std::size_t(info.width) * std::size_t(info.height) > kMaxEnvironmentTexels ||
        double(info.width) * double(info.height) > double(bytes.size()) * kMaxPixelsPerByte)
        throw Error("OpenEXR image of " + std::to_string(info.width) + "x" + std::to_string(info.height) +
                    " texels is too large for a texture or for its file size");
    const auto rgb = beautyChannels(info.channels);
    if (!rgb) throw Error("the OpenEXR image has no R, G, B or Y channels");
    std::vector<std::string> wanted{(*rgb)[0], (*rgb)[1], (*rgb)[2]};
    const bool alpha = std::find(info.channels.begin(), info.channels.end(), "A") != info.channels.end();
    if (alpha) wanted.push_back("A");
    std::sort(wanted.begin(), wanted.end());
    wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
    const ExrChannels exr = decodeExrChannels(bytes, name, wanted);
    Texture tex = makeTexture(name, exr.width, exr.height, srgb);
    const std::size_t n = std::size_t(exr.width) * std::size_t(exr.height);
    for (int c = 0; c < 3; ++c) {
        const std::vector<float>& v = exr.channels.at((*rgb)[std::size_t(c)]);
        for (std::size_t i = 0; i < n; ++i) tex.rgba[4 * i + std::size_t(c)] = toByte(v[i], srgb);
    }
    for (std::size_t i = 0; i < n; ++i) tex.rgba[4 * i + 3] = alpha ? toByte(exr.channels.at("A")[i], false) : 255;
    return tex;
}

}  // namespace

std::optional<Texture> decodeTexture(std::string_view bytes, const std::string& name, bool srgb,
                                     std::string* why) {
    if (bytes.empty()) {
        setWhy(why, "image data is empty");
        return std::nullopt;
    }
    if (bytes.size() > std::size_t(INT_MAX)) {
        setWhy(why, "image data is larger than 2 GiB");
        return std::nullopt;
    }
    try {
        if (isTiff(bytes)) return fromTiff(decodeTiff(bytes, name, kMaxTextureSide, kMaxPixelsPerByte), name, srgb);
        if (startsWith(bytes, kExrMagic)) return decodeExrTexture(bytes, name, srgb);
        if (startsWith(bytes, "#?")) return fromLinear(decodeEnvironmentMap(bytes, name), name, srgb);
    } catch (const Error& e) {
        setWhy(why, e.what());
        return std::nullopt;
    }
    // stb_image also decodes PSD, PIC and PNM; those are not texture formats we promise, and
    // keeping their decoders away from untrusted input narrows what a hostile file can reach.
    if (startsWith(bytes, "8BPS") || startsWith(bytes, "\x53\x80\xF6\x34") ||
        (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '7')) {
        setWhy(why, "unsupported image format (PNG, JPEG, TGA, BMP, GIF, TIFF, OpenEXR and Radiance HDR are read)");
        return std::nullopt;
    }
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int length = static_cast<int>(bytes.size());
    int w = 0, h = 0, comp = 0;
    // Header first: the size is checked before anything is allocated for the pixels.
    if (!stbi_info_from_memory(data, length, &w, &h, &comp)) {
        const char* reason = stbi_failure_reason();
        setWhy(why, std::string("not a readable image (") + (reason ? reason : "unknown format") + ")");
        return std::nullopt;
    }
    if (w <= 0 || h <= 0 || w > kMaxTextureSide || h > kMaxTextureSide) {
        setWhy(why, "image is " + std::to_string(w) + "x" + std::to_string(h) + "; sides must be 1.." +
                        std::to_string(kMaxTextureSide));
        return std::nullopt;
    }
    // No format we read packs more than ~8k pixels into a byte (deflate tops out near 1032:1 on
    // 1-bit PNG rows). A tiny file claiming a huge image would only make the decoder allocate.
    if (double(w) * double(h) > double(bytes.size()) * kMaxPixelsPerByte) {
        setWhy(why, "image header claims " + std::to_string(w) + "x" + std::to_string(h) + " pixels, more than its " +
                        std::to_string(bytes.size()) + " bytes can hold");
        return std::nullopt;
    }
    int dw = 0, dh = 0;
    stbi_uc* pixels = stbi_load_from_memory(data, length, &dw, &dh, &comp, 4);
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        setWhy(why, std::string("cannot decode image (") + (reason ? reason : "unknown error") + ")");
        return std::nullopt;
    }
    if (dw != w || dh != h) {  // header and decoder disagree: do not trust either
        stbi_image_free(pixels);
        setWhy(why, "image size changed while decoding");
        return std::nullopt;
    }
    Texture tex;
    tex.name = name;
    tex.width = w;
    tex.height = h;
    tex.srgb = srgb;
    tex.rgba.assign(pixels, pixels + std::size_t(w) * std::size_t(h) * 4);
    stbi_image_free(pixels);
    return tex;
}

std::optional<Texture> loadTextureFile(const std::filesystem::path& path, bool srgb, std::string* why) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        setWhy(why, "file not found");
        return std::nullopt;
    }
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) {
        setWhy(why, "cannot read file size: " + ec.message());
        return std::nullopt;
    }
    if (size > kMaxTextureFileBytes) {
        setWhy(why, "file is larger than " + std::to_string(kMaxTextureFileBytes >> 20) + " MiB");
        return std::nullopt;
    }
    std::ifstream in(path, std::ios::binary);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    if (!in || !in.read(bytes.data(), static_cast<std::streamsize>(size))) {
        setWhy(why, "cannot read file");
        return std::nullopt;
    }
    return decodeTexture(bytes, path.filename().string(), srgb, why);
}

Texture missingTexture(const std::string& name) {
    Texture tex;
    tex.name = name;
    tex.width = 8;
    tex.height = 8;
    tex.srgb = true;
    tex.rgba.resize(8 * 8 * 4);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            std::uint8_t* p = &tex.rgba[std::size_t(y * 8 + x) * 4];
            const bool magenta = ((x / 2) + (y / 2)) % 2 == 0;
            p[0] = magenta ? 255 : 0;
            p[1] = 0;
            p[2] = magenta ? 255 : 0;
            p[3] = 255;
        }
    return tex;
}

}  // namespace penumbra
