// The dungeon's textures, taken from Freedoom Phase 1 (Debian's freedoom package, BSD-licensed,
// installed by scripts/setup.sh and read at run time, never committed) as the WebGPU renderer
// textures its dungeon from a texture atlas.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "scene/scene.h"

namespace penumbra {

const char* freedoomWadPath();  // /usr/share/games/doom/freedoom1.wad

struct DungeonTextures {
    std::vector<Texture> textures;  // the scene's textures; the indices below point into it
    int wall = -1, floor = -1, ceiling = -1;
    float wallMetres = 4.0f;   // the wall texture's width and height on the wall (1 texel = 1 Doom unit = 1/32 m)
    float wallHeightMetres = 4.0f;
    float flatMetres = 2.0f;   // a flat's side (64 texels: one tile)
};

// The wall texture and the floor and ceiling flats from `wad`. nullopt, with a warning line saying
// that the dungeon is flat-coloured and why, when the file is missing or cannot be read.
std::optional<DungeonTextures> loadDungeonTextures(const std::filesystem::path& wad);

}  // namespace penumbra
