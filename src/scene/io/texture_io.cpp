#include "scene/io/texture_io.h"

#include <stb_image.h>

#include <climits>
#include <cstring>
#include <fstream>
#include <system_error>

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
    // stb_image also decodes PSD, HDR, PIC and PNM; those are not texture formats we promise, and
    // keeping their decoders away from untrusted input narrows what a hostile file can reach.
    if (startsWith(bytes, "8BPS") || startsWith(bytes, "#?") || startsWith(bytes, "\x53\x80\xF6\x34") ||
        (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '7')) {
        setWhy(why, "unsupported image format (PNG, JPEG, TGA, BMP and GIF are read)");
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
