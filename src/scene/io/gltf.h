// glTF 2.0, .gltf and .glb (through tinygltf).
#pragma once

#include <filesystem>
#include <string_view>

#include "scene/scene.h"

namespace penumbra {

Scene loadGltf(const std::filesystem::path& path);
// For fuzzing and tests: the file's bytes; external buffers and images are looked up relative
// to `baseDir`.
Scene loadGltfFromMemory(std::string_view bytes, const std::filesystem::path& baseDir, const std::string& name);

}  // namespace penumbra
