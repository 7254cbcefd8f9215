// Doom's player movement as pure functions over a WalkMap, in map units and seconds: a square
// player 32 units wide and 56 tall that steps up at most 24 units, fits only where the opening
// is 56 tall, cannot cross one-sided or blocking lines, slides along walls and falls under Doom's
// gravity. The rules follow id Software's P_CheckPosition / P_TryMove / P_ZMovement; the sliding
// is simpler than P_SlideMove (along the nearest blocking line, then along the axes).
#pragma once

#include <optional>

#include "scene/walk/walk_map.h"

namespace penumbra::walk {

// Doom's player (the Doom source's MT_PLAYER and p_local.h), map units.
constexpr double kPlayerRadius = 16;  // half the side of the square the player occupies
constexpr double kPlayerHeight = 56;
constexpr double kEyeHeight = 41;  // above the feet (VIEWHEIGHT)
constexpr double kMaxStepUp = 24;
constexpr double kGravity = 1225;   // units/s^2: one unit per tic per tic at 35 tics per second
constexpr double kWalkSpeed = 292;  // units/s: Doom's top walking speed (8.3 units per tic)
constexpr double kRunSpeed = 583;   // units/s: running (Shift)
// Moves are cut into pieces no longer than this, so a fast move cannot jump over a thin wall.
constexpr double kMaxSubstep = kPlayerRadius / 2;

struct WalkState {
    double x = 0, y = 0;  // centre of the player on the ground plane
    double z = 0;         // height of the feet
    double vz = 0;        // vertical velocity (falling is negative), units/s
};

// What the player's box at (x, y) touches: the highest floor and lowest ceiling of the sectors
// it overlaps, or blocked when it overlaps an impassable line or lies outside the map.
struct Opening {
    bool blocked = true;
    double floor = 0, ceiling = 0;
};
Opening openingAt(const WalkMap& map, double x, double y);

// Whether the player with feet at height z may stand at (x, y): not blocked, the opening at
// least the player's height, the ceiling above the head, and the floor at most a step up.
bool canStandAt(const WalkMap& map, double x, double y, double z, Opening* opening = nullptr);

// A player at (x, y) with feet at z, clamped between the floor and the ceiling there; none when
// the player does not fit at (x, y) at all (inside a wall, outside the map, too low a sector).
std::optional<WalkState> placePlayer(const WalkMap& map, double x, double y, double z);

// Advances the player by dt seconds while it tries to move with the horizontal velocity
// (vx, vy) in units/s: moves that would leave a valid position slide instead; gravity pulls it
// down to the floor and steps up lift it. Deterministic; a non-positive or non-finite dt, or a
// non-finite velocity, changes nothing.
WalkState stepWalk(const WalkMap& map, WalkState state, double vx, double vy, double dt);

}  // namespace penumbra::walk
