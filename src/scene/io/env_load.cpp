#include "scene/io/env_load.h"

#include <stb_image.h>

#include <climits>
#include <cstdint>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "core/error.h"
#include "core/log.h"
#include "image/exr_layers.h"
#include "scene/environment.h"
#include "scene/io/load.h"
#include "scene/io/texture_io.h"
#include "scene/io/tiff_io.h"
#include "shared/color.h"

namespace penumbra {
namespace {

// Bounds on how many pixels a file of a given size can honestly describe, so that a tiny file
// claiming a huge image is refused before the decoder allocates for it. RGBE run-length coding
// packs at most 127 pixels of one channel into 2 bytes (about 16 pixels a byte); EXR's zlib
// tops out near 1032:1 on half floats (about 170 pixels a byte, ~8k with a constant image's
// predictor), so its bound is looser. (PIZ and DWA could pack a constant image tighter still;
// such a map is refused rather than letting a few hundred bytes claim 2^25 texels.)
constexpr double kMaxHdrPixelsPerByte = 32.0;
constexpr double kMaxExrPixelsPerByte = 8192.0;
// TIFF (deflate, LZW): 1-bit rows at deflate's 1032:1, like PNG.
constexpr double kMaxTiffPixelsPerByte = 8.0 * 1032.0;
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(1) << 30;

bool startsWith(std::string_view bytes, std::string_view magic) {
    return bytes.size() >= magic.size() && std::memcmp(bytes.data(), magic.data(), magic.size()) == 0;
}

void checkSize(const std::string& name, long long w, long long h, std::size_t bytes, double pixelsPerByte) {
    if (w <= 0 || h <= 0 || w > kMaxEnvironmentSide || h > kMaxEnvironmentSide ||
        std::size_t(w) * std::size_t(h) > kMaxEnvironmentTexels)
        throw Error(name + ": environment map is " + std::to_string(w) + "x" + std::to_string(h) + "; sides must be 1.." +
                    std::to_string(kMaxEnvironmentSide) + " and the map at most " +
                    std::to_string(kMaxEnvironmentTexels) + " texels");
    if (double(w) * double(h) > double(bytes) * pixelsPerByte)
        throw Error(name + ": header claims " + std::to_string(w) + "x" + std::to_string(h) +
                    " pixels, more than the file's " + std::to_string(bytes) + " bytes can hold (truncated or corrupt)");
}

// Copies interleaved float pixels (`channels` per pixel, RGB first) into a map.
EnvironmentMap toMap(const std::string& name, const float* pixels, int w, int h, int channels) {
    EnvironmentMap map;
    map.name = name;
    map.width = w;
    map.height = h;
    map.radiance.resize(std::size_t(w) * std::size_t(h));
    std::size_t clamped = 0;
    for (std::size_t i = 0; i < map.radiance.size(); ++i) {
        const float* p = pixels + i * std::size_t(channels);
        Vec3 v{p[0], p[1], p[2]};
        if (!isFinite(v))
            throw Error(name + ": pixel " + std::to_string(i % std::size_t(w)) + "," + std::to_string(i / std::size_t(w)) +
                        " is not finite (NaN or infinity)");
        if (minComponent(v) < 0) {
            v = Vec3{std::max(v.x, 0.0f), std::max(v.y, 0.0f), std::max(v.z, 0.0f)};
            ++clamped;
        }
        map.radiance[i] = v;
    }
    if (clamped) logWarning(name + ": " + std::to_string(clamped) + " pixels had negative values, set to 0");
    return map;
}

// stb_image's RGBE reader trusts its input more than a loader may: past the end of the data it
// reads zeros (a truncated file loads with a black band), and the Debian version loops forever
// on a run-length count of 0. So the pixel data is walked here first, the way stb will decode
// it, and refused unless every scanline is complete and well formed. Flat (uncompressed) data
// is what stb reads when the width is outside [8, 32768) or the first scanline lacks the
// run-length marker (2, 2, width).
void checkRgbeData(std::string_view bytes, const std::string& name, int w, int h) {
    const std::size_t blank = bytes.find("\n\n");
    const std::size_t resolutionEnd = blank == std::string_view::npos ? blank : bytes.find('\n', blank + 2);
    if (resolutionEnd == std::string_view::npos) throw Error(name + ": Radiance HDR header has no resolution line");
    const std::string_view data = bytes.substr(resolutionEnd + 1);
    const auto at = [&](std::size_t i) { return static_cast<unsigned char>(data[i]); };
    const auto truncated = [&]() {
        return Error(name + ": Radiance HDR pixel data is truncated or corrupt");
    };
    const bool runLength = w >= 8 && w < 32768 && data.size() >= 4 && at(0) == 2 && at(1) == 2 && (at(2) & 0x80) == 0;
    if (!runLength) {
        if (data.size() < std::size_t(w) * std::size_t(h) * 4)
            throw Error(name + ": Radiance HDR pixel data is truncated (" + std::to_string(data.size()) + " of " +
                        std::to_string(std::size_t(w) * std::size_t(h) * 4) + " bytes)");
        return;
    }
    std::size_t pos = 0;
    for (int row = 0; row < h; ++row) {
        if (pos + 4 > data.size()) throw truncated();
        if (at(pos) != 2 || at(pos + 1) != 2 || ((at(pos + 2) << 8) | at(pos + 3)) != w)
            throw Error(name + ": Radiance HDR scanline " + std::to_string(row) + " is corrupt (bad run-length marker)");
        pos += 4;
        for (int channel = 0; channel < 4; ++channel) {
            for (int filled = 0; filled < w;) {
                if (pos >= data.size()) throw truncated();
                int count = at(pos++);
                const bool run = count > 128;
                if (run) count -= 128;
                if (count == 0 || count > w - filled)
                    throw Error(name + ": Radiance HDR scanline " + std::to_string(row) + " is corrupt (bad run length)");
                pos += run ? 1 : std::size_t(count);
                if (pos > data.size()) throw truncated();
                filled += count;
            }
        }
    }
}

struct FreeDeleter {
    void operator()(void* p) const { std::free(p); }
};

EnvironmentMap decodeHdr(std::string_view bytes, const std::string& name) {
    if (bytes.size() > std::size_t(INT_MAX)) throw Error(name + ": file is larger than 2 GiB");
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int length = int(bytes.size());
    int w = 0, h = 0, comp = 0;
    if (!stbi_info_from_memory(data, length, &w, &h, &comp) || !stbi_is_hdr_from_memory(data, length)) {
        const char* reason = stbi_failure_reason();
        throw Error(name + ": not a readable Radiance HDR file (" + (reason ? reason : "bad header") + ")");
    }
    checkSize(name, w, h, bytes.size(), kMaxHdrPixelsPerByte);
    checkRgbeData(bytes, name, w, h);
    std::unique_ptr<float, FreeDeleter> pixels(stbi_loadf_from_memory(data, length, &w, &h, &comp, 3));
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        throw Error(name + ": corrupt Radiance HDR data (" + (reason ? reason : "unknown") + ")");
    }
    return toMap(name, pixels.get(), w, h, 3);
}

// Through the OpenEXR library: scanline and tiled files, the first part of multi-part files,
// every compression (DWAA/DWAB included, which tinyexr cannot read). The header's size is
// checked before anything is allocated for the pixels.
EnvironmentMap decodeExr(std::string_view bytes, const std::string& name) {
    const ExrHeaderInfo info = readExrHeader(bytes, name);
    checkSize(name, info.width, info.height, bytes.size(), kMaxExrPixelsPerByte);
    const auto rgb = beautyChannels(info.channels);
    if (!rgb) throw Error(name + ": the OpenEXR file has no R, G, B or Y channels");
    const ExrChannels exr = decodeExrChannels(bytes, name, {(*rgb)[0], (*rgb)[1], (*rgb)[2]});
    const std::vector<float>&r = exr.channels.at((*rgb)[0]), &g = exr.channels.at((*rgb)[1]), &b = exr.channels.at((*rgb)[2]);
    std::vector<float> pixels(r.size() * 3);
    for (std::size_t i = 0; i < r.size(); ++i) {
        pixels[3 * i] = r[i];
        pixels[3 * i + 1] = g[i];
        pixels[3 * i + 2] = b[i];
    }
    return toMap(name, pixels.data(), exr.width, exr.height, 3);
}

// TIFF: 32-bit float panoramas as they are; integer ones are sRGB-encoded colours.
EnvironmentMap decodeTiffMap(std::string_view bytes, const std::string& name) {
    const TiffPixels tiff = decodeTiff(bytes, name, kMaxEnvironmentSide, kMaxTiffPixelsPerByte);
    checkSize(name, tiff.width, tiff.height, bytes.size(), kMaxTiffPixelsPerByte);
    const std::size_t n = std::size_t(tiff.width) * std::size_t(tiff.height);
    std::vector<float> rgb(n * 3);
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
            rgb[3 * i + std::size_t(c)] = tiff.isFloat ? tiff.rgbaFloat[4 * i + std::size_t(c)]
                                                       : shader::srgbToLinear(tiff.rgba8[4 * i + std::size_t(c)] / 255.0f);
    return toMap(name, rgb.data(), tiff.width, tiff.height, 3);
}

bool isLdrImage(std::string_view bytes) {
    return startsWith(bytes, "\x89PNG") || startsWith(bytes, "\xff\xd8\xff") || startsWith(bytes, "BM");
}

// PNG, JPEG, BMP panoramas (low dynamic range): sRGB-encoded, decoded to linear light.
EnvironmentMap decodeLdrMap(std::string_view bytes, const std::string& name) {
    std::string why;
    const std::optional<Texture> tex = decodeTexture(bytes, name, true, &why);
    if (!tex) throw Error(name + ": " + why);
    checkSize(name, tex->width, tex->height, bytes.size(), kMaxExrPixelsPerByte);
    std::vector<float> rgb(std::size_t(tex->width) * std::size_t(tex->height) * 3);
    for (std::size_t i = 0; i < rgb.size() / 3; ++i)
        for (int c = 0; c < 3; ++c) rgb[3 * i + std::size_t(c)] = shader::srgbToLinear(tex->rgba[4 * i + std::size_t(c)] / 255.0f);
    return toMap(name, rgb.data(), tex->width, tex->height, 3);
}

}  // namespace

EnvironmentMap decodeEnvironmentMap(std::string_view bytes, const std::string& name) {
    if (startsWith(bytes, "#?")) return decodeHdr(bytes, name);
    if (startsWith(bytes, "\x76\x2f\x31\x01")) return decodeExr(bytes, name);
    if (isTiff(bytes)) return decodeTiffMap(bytes, name);
    if (isLdrImage(bytes)) return decodeLdrMap(bytes, name);
    throw Error(name + ": not an environment map (Radiance .hdr, OpenEXR .exr, TIFF, PNG and JPEG files are read)");
}

EnvironmentMap loadEnvironmentMap(const std::filesystem::path& path) {
    return decodeEnvironmentMap(readFileBytes(path, std::size_t(kMaxFileBytes)), path.string());
}

}  // namespace penumbra
