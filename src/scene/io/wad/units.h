// Where a Doom map sits in a Penumbra scene: map units become metres at 32 units per metre, and
// Doom's (x east, y north, z up) becomes (x, z, -y) with y up. The one place this mapping lives:
// the WAD loader builds geometry with it and walking (scene/walk/) converts the camera with it.
#pragma once

#include "core/vec.h"

namespace penumbra::wad {

constexpr float kUnitsPerMetre = 32.0f;

// A map point (x, y on the ground, z = height) in scene coordinates. Linear, so it maps
// directions too.
inline Vec3 mapToScene(double x, double y, double z) {
    return Vec3(float(x), float(z), float(-y)) / kUnitsPerMetre;
}
inline Vec3 mapToScene(Vec3 map) { return mapToScene(map.x, map.y, map.z); }
// The same with the height second, in the order the WAD loaders write points (x, height, y).
inline Vec3 toWorld(double x, double height, double y) { return mapToScene(x, y, height); }

// The inverse: a scene point as (x, y, z = height) in map units.
inline Vec3 sceneToMap(Vec3 scene) { return Vec3(scene.x, -scene.z, scene.y) * kUnitsPerMetre; }

}  // namespace penumbra::wad
