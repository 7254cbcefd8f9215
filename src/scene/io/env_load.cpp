#include "scene/io/env_load.h"

#include <stb_image.h>
#include <tinyexr.h>

#include <climits>
#include <cstdint>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "core/error.h"
#include "core/log.h"
#include "scene/environment.h"
#include "scene/io/load.h"

namespace penumbra {
namespace {

// Bounds on how many pixels a file of a given size can honestly describe, so that a tiny file
// claiming a huge image is refused before the decoder allocates for it. RGBE run-length coding
// packs at most 127 pixels of one channel into 2 bytes (about 16 pixels a byte); EXR's zlib
// tops out near 1032:1 on half floats (about 170 pixels a byte, ~8k with a constant image's
// predictor), so its bound is looser.
constexpr double kMaxHdrPixelsPerByte = 32.0;
constexpr double kMaxExrPixelsPerByte = 8192.0;
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

// Debian's tinyexr asserts (aborting the process) when a header's "type" attribute disagrees with
// the version field's tiled flag or names an unknown type, so the header's attribute list is
// walked here first: every attribute must fit in the file, and "type" must be a scanline image
// with the flag clear or a tiled image with it set.
void checkExrHeaderBeforeTinyexr(std::string_view bytes, bool tiled, const std::string& name) {
    std::size_t at = 8;  // after the magic number and the version field
    auto readString = [&](const char* what) {
        const std::size_t end = bytes.find('\0', at);
        if (end == std::string_view::npos || end - at > 255)
            throw Error(name + ": corrupt OpenEXR header (" + what + " runs past the end)");
        std::string_view text = bytes.substr(at, end - at);
        at = end + 1;
        return text;
    };
    while (true) {
        const std::string_view attribute = readString("an attribute name");
        if (attribute.empty()) return;  // the header's terminating empty name
        const std::string_view type = readString("an attribute type");
        if (bytes.size() - at < 4) throw Error(name + ": corrupt OpenEXR header (attribute size missing)");
        std::uint32_t size = 0;
        for (int k = 3; k >= 0; --k) size = (size << 8) | static_cast<unsigned char>(bytes[at + std::size_t(k)]);
        at += 4;
        if (size > bytes.size() - at) throw Error(name + ": corrupt OpenEXR header (attribute runs past the end)");
        (void)type;  // tinyexr reads "type" whatever type name it carries, so this does too
        if (attribute == "type") {
            // Like tinyexr: the text up to its first NUL; an empty one means no type.
            std::string_view value = bytes.substr(at, size);
            value = value.substr(0, value.find('\0'));
            const bool ok = value.empty() || (value == "scanlineimage" && !tiled) || (value == "tiledimage" && tiled);
            if (!ok)
                throw Error(name + ": OpenEXR image type '" + std::string(value.substr(0, 32)) +
                            "' is not supported or disagrees with the file's tiled flag");
        }
        at += size;
    }
}

EnvironmentMap decodeExr(std::string_view bytes, const std::string& name) {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const char* err = nullptr;
    auto fail = [&](const std::string& what) -> Error {
        std::string message = name + ": " + what + (err ? std::string(" (") + err + ")" : std::string());
        if (err) FreeEXRErrorMessage(err);
        return Error(message);
    };
    EXRVersion version;
    if (ParseEXRVersionFromMemory(&version, data, bytes.size()) != TINYEXR_SUCCESS) throw fail("not a readable OpenEXR file");
    if (version.multipart || version.non_image) throw fail("multi-part and deep OpenEXR files are not supported");
    checkExrHeaderBeforeTinyexr(bytes, version.tiled != 0, name);
    EXRHeader header;
    InitEXRHeader(&header);
    if (ParseEXRHeaderFromMemory(&header, &version, data, bytes.size(), &err) != TINYEXR_SUCCESS) {
        // A header that fails part-way holds what was parsed so far (channel names and the like).
        FreeEXRHeader(&header);
        throw fail("corrupt OpenEXR header");
    }
    const long long w = (long long)header.data_window.max_x - header.data_window.min_x + 1;
    const long long h = (long long)header.data_window.max_y - header.data_window.min_y + 1;
    FreeEXRHeader(&header);
    checkSize(name, w, h, bytes.size(), kMaxExrPixelsPerByte);
    float* rgba = nullptr;
    int width = 0, height = 0;
    if (LoadEXRFromMemory(&rgba, &width, &height, data, bytes.size(), &err) != TINYEXR_SUCCESS)
        throw fail("corrupt OpenEXR data");
    std::unique_ptr<float, FreeDeleter> pixels(rgba);
    if (width != w || height != h) throw fail("OpenEXR image size differs from its header");
    return toMap(name, pixels.get(), width, height, 4);
}

}  // namespace

EnvironmentMap decodeEnvironmentMap(std::string_view bytes, const std::string& name) {
    if (startsWith(bytes, "#?")) return decodeHdr(bytes, name);
    if (startsWith(bytes, "\x76\x2f\x31\x01")) return decodeExr(bytes, name);
    throw Error(name + ": not an environment map (Radiance .hdr and OpenEXR .exr files are read)");
}

EnvironmentMap loadEnvironmentMap(const std::filesystem::path& path) {
    return decodeEnvironmentMap(readFileBytes(path, std::size_t(kMaxFileBytes)), path.string());
}

}  // namespace penumbra
