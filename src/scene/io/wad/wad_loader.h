// Doom WAD levels (Doom 1 ExMy and Doom 2 MAPxx, vanilla map format).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace penumbra {

// How a level is lit and drawn (docs/SCENES.md, "Doom WAD levels").
struct WadOptions {
    float glow = 1.0f;         // scales the light of glowing textures and flats; 0: nothing glows
    float sectorLight = 1.0f;  // scales the fill light that sector light levels give; 0: none
    Filter filter = Filter::Nearest;  // Doom's crisp texels, or bilinear
};

// Throws UsageError for a negative or non-finite scale.
void validateWadOptions(const WadOptions& options);

// map: "E1M1", "MAP01", ...; empty picks the first map in the file.
Scene loadWad(const std::filesystem::path& path, const std::string& map, const WadOptions& options = {});
Scene loadWadFromMemory(std::string_view bytes, const std::string& map, const std::string& name,
                        const WadOptions& options = {});
// The map names in a WAD, in directory order.
std::vector<std::string> wadMapNames(std::string_view bytes);

}  // namespace penumbra
