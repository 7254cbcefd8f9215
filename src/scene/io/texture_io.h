// Decoding image files into scene textures, with a visible fallback: PNG, JPEG, TGA, BMP and GIF
// through stb_image, TIFF through libtiff, OpenEXR through OpenEXR (any compression) and Radiance
// HDR (linear formats are sRGB-encoded for colour textures, clipped at 1).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace penumbra {

// Largest texture side accepted; larger images are refused rather than allocated.
constexpr int kMaxTextureSide = 16384;

// Decodes image bytes (told apart by content) to RGBA8; nullopt (with *why set) when they are not
// a readable image.
std::optional<Texture> decodeTexture(std::string_view bytes, const std::string& name, bool srgb,
                                     std::string* why = nullptr);
std::optional<Texture> loadTextureFile(const std::filesystem::path& path, bool srgb, std::string* why = nullptr);

// The magenta/black checker that stands in for a missing texture, so the gap is obvious.
Texture missingTexture(const std::string& name);

}  // namespace penumbra
