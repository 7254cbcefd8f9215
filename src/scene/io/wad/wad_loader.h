// Doom WAD levels (Doom 1 ExMy and Doom 2 MAPxx, vanilla map format).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace penumbra {

// map: "E1M1", "MAP01", ...; empty picks the first map in the file.
Scene loadWad(const std::filesystem::path& path, const std::string& map);
Scene loadWadFromMemory(std::string_view bytes, const std::string& map, const std::string& name);
// The map names in a WAD, in directory order.
std::vector<std::string> wadMapNames(std::string_view bytes);

}  // namespace penumbra
