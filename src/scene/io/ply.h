// Stanford PLY: ASCII, binary little and big endian, and gzip-compressed (.ply.gz).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace penumbra {

Scene loadPly(const std::filesystem::path& path);
// For fuzzing and tests: a PLY file's bytes (gzip-compressed or not); `name` appears in messages.
Scene loadPlyFromMemory(std::string_view bytes, const std::string& name);

}  // namespace penumbra
