// Wavefront OBJ + MTL (through tinyobjloader).
#pragma once

#include <filesystem>
#include <string_view>

#include "scene/scene.h"

namespace penumbra {

Scene loadObj(const std::filesystem::path& path);
// For fuzzing and tests: the OBJ text and the MTL text (empty: none). Textures named by the
// MTL are looked up relative to `baseDir`.
Scene loadObjFromMemory(std::string_view obj, std::string_view mtl, const std::filesystem::path& baseDir,
                        const std::string& name);

}  // namespace penumbra
