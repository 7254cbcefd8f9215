// Doom's built-in animated textures and flats (the animdefs table of the game's p_spec.c): each
// cycle runs through every flat between its first and last name in directory order, or every
// wall texture between them in TEXTURE1/TEXTURE2 order, so a WAD can add frames; every frame
// shows for 8 tics of 1/35 s.
#pragma once

#include <string>
#include <vector>

namespace penumbra::wad {

constexpr float kSecondsPerTic = 1.0f / 35.0f;
constexpr int kTicsPerAnimationFrame = 8;
constexpr float kSecondsPerAnimationFrame = kTicsPerAnimationFrame * kSecondsPerTic;
constexpr std::size_t kMaxAnimationFrames =
    64;  // longer "cycles" in a hostile WAD are not animated

struct AnimationDef {
    bool texture;  // wall texture (true) or flat
    const char* first;
    const char* last;
};

// The game's table, Doom and Doom II.
const std::vector<AnimationDef>& animationDefs();

// The cycles of `defs` found in `orderedNames` (the WAD's flats or textures in order, each name
// once): the names from first to last inclusive. Cycles whose first or last name is missing, that
// run backwards, have fewer than 2 or more than kMaxAnimationFrames frames are left out.
std::vector<std::vector<std::string>> findCycles(const std::vector<std::string>& orderedNames,
                                                 bool textures);

}  // namespace penumbra::wad
