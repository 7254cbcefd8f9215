// Reading equirectangular environment maps into linear float RGB: Radiance .hdr (RGBE, through
// stb_image), OpenEXR .exr (through the OpenEXR library, any compression, DWA included), TIFF
// (32-bit float, or integer sRGB; libtiff), and PNG, JPEG or BMP panoramas (sRGB, stb_image).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace penumbra {

// Decodes the bytes of any of those (told apart by their magic numbers, not the name). Throws Error
// naming `name` and the problem: unknown format, corrupt data, sizes outside
// kMaxEnvironmentSide / kMaxEnvironmentTexels, non-finite radiance. Negative values (from
// filtering in other tools) are clamped to 0.
EnvironmentMap decodeEnvironmentMap(std::string_view bytes, const std::string& name);

EnvironmentMap loadEnvironmentMap(const std::filesystem::path& path);

}  // namespace penumbra
