// Doom units and axes in the scene: 32 units per metre, Doom (x, y, z up) as (x, z, -y), y up.
#pragma once

#include "core/vec.h"

namespace penumbra::wad {

constexpr float kUnitsPerMetre = 32.0f;

inline Vec3 toWorld(double x, double height, double y) {
    return Vec3(float(x), float(height), float(-y)) / kUnitsPerMetre;
}

}  // namespace penumbra::wad
