// A map's things in the scene: what Doom draws of them as sprites (sprites.h, things.h), and the
// lamps, candles and torches as lights besides.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/io/wad/map.h"
#include "scene/io/wad/textures.h"
#include "scene/io/wad/wad_file.h"
#include "scene/io/wad/wad_loader.h"
#include "scene/scene.h"

namespace penumbra::wad {

// A thing the player can take away (a key), whose sprite has a material of its own, so that it
// can vanish alone (doom::KeyMaterial).
struct TakeableSprite {
    std::size_t thing = 0;  // index in the map's things
    std::uint32_t material = 0;
};

// Adds a sprite (Scene::sprites, with a material per sprite frame, and one per key) for every
// thing with a picture and a point light for every lamp, for the single-player game at medium
// skill. Textures are appended to `textures`, whose list becomes the scene's. Returns the keys'.
std::vector<TakeableSprite> placeThings(const WadFile& wad, const MapData& map, TextureLibrary& textures,
                                        const WadOptions& options, Scene& scene);

}  // namespace penumbra::wad
