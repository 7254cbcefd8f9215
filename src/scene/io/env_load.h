// Reading equirectangular environment maps: Radiance .hdr (RGBE, through stb_image) and
// OpenEXR .exr (through tinyexr), into linear float RGB.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace penumbra {

// Decodes .hdr or .exr bytes (told apart by their magic numbers, not the name). Throws Error
// naming `name` and the problem: unknown format, corrupt data, sizes outside
// kMaxEnvironmentSide / kMaxEnvironmentTexels, non-finite radiance. Negative values (from
// filtering in other tools) are clamped to 0.
EnvironmentMap decodeEnvironmentMap(std::string_view bytes, const std::string& name);

EnvironmentMap loadEnvironmentMap(const std::filesystem::path& path);

}  // namespace penumbra
