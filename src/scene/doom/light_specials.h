// Doom's sector light specials as state machines stepped once per tic (p_lights.c): random
// flashes (sector special 1), strobes fast and slow (2, 3, 4; synchronised 12, 13), glowing
// (8) and fire flicker (17). Doom draws their random parts from its fixed random table; here a
// small generator seeded per level, so runs repeat too (the sequences differ from the game's).
#pragma once

#include <cstdint>
#include <optional>
#include <variant>

namespace penumbra::doom {

constexpr int kStrobeBright = 5;  // STROBEBRIGHT: tics at full light
constexpr int kFastDark = 15;     // FASTDARK
constexpr int kSlowDark = 35;     // SLOWDARK
constexpr int kGlowSpeed = 8;     // GLOWSPEED: light levels per tic

// The level's light random numbers: 0..255, the same sequence every run.
class LightRandom {
public:
    int next() {
        state_ = state_ * 1103515245u + 12345u;
        return int((state_ >> 16) & 0xFF);
    }

private:
    std::uint32_t state_ = 1;
};

struct LightFlash {
    int sector = 0, minLight = 0, maxLight = 0, count = 1;
};
struct StrobeFlash {
    int sector = 0, minLight = 0, maxLight = 0, darkTime = kSlowDark, brightTime = kStrobeBright, count = 1;
};
struct Glow {
    int sector = 0, minLight = 0, maxLight = 0, direction = -1;
};
struct FireFlicker {
    int sector = 0, minLight = 0, maxLight = 0, count = 4;
};
using LightThinker = std::variant<LightFlash, StrobeFlash, Glow, FireFlicker>;

// The thinker a sector special starts, given the sector's light and the dimmest of its
// neighbours' (P_FindMinSurroundingLight); none for specials that are not lights.
std::optional<LightThinker> makeLightThinker(int special, int sector, int light, int dimmestNeighbour, LightRandom& random);

// One tic: the sector's light level, changed or not.
int ticLight(LightThinker& thinker, int light, LightRandom& random);
int lightSector(const LightThinker& thinker);

}  // namespace penumbra::doom
