// Decoding image files into scene textures (through stb_image), with a visible fallback.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace penumbra {

// Largest texture side accepted; larger images are refused rather than allocated.
constexpr int kMaxTextureSide = 16384;

// Decodes PNG/JPEG/TGA/BMP bytes to RGBA8; nullopt (with *why set) when they are not an image.
std::optional<Texture> decodeTexture(std::string_view bytes, const std::string& name, bool srgb,
                                     std::string* why = nullptr);
std::optional<Texture> loadTextureFile(const std::filesystem::path& path, bool srgb, std::string* why = nullptr);

// The magenta/black checker that stands in for a missing texture, so the gap is obvious.
Texture missingTexture(const std::string& name);

}  // namespace penumbra
