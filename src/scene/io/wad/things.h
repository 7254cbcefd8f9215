// Doom and Doom II thing types (the game's mobjinfo table) as this importer draws them: the
// sprite and frame each shows when a level starts (monsters standing, corpses in their last
// death frame), whether that frame is drawn at full brightness, and, for things that hang from
// the ceiling, their height. Player starts, teleport destinations and the boss spawner's markers
// have no picture and are not listed.
#pragma once

#include <cstdint>

namespace penumbra::wad {

struct ThingType {
    std::uint16_t type;
    char sprite[5];   // 4-letter sprite name
    char frame;       // 'A', 'B', ...
    bool fullBright;  // FF_FULLBRIGHT: shown at full brightness (lamps, torches, power-ups)
    int hangHeight;   // > 0: MF_SPAWNCEILING, it hangs this many units below the ceiling
};

// nullptr for a type with no picture (or unknown to Doom and Doom II).
const ThingType* thingType(std::uint16_t type);

// Thing flags: which skills a thing appears on, and multiplayer only.
constexpr std::uint16_t kThingMediumSkill = 0x0002;  // "Hurt me plenty", the one imported
constexpr std::uint16_t kThingMultiplayer = 0x0010;

// Whether a thing with these flags is in the single-player game at medium skill.
inline bool inSinglePlayerMedium(std::uint16_t flags) {
    return (flags & kThingMediumSkill) != 0 && (flags & kThingMultiplayer) == 0;
}

}  // namespace penumbra::wad
