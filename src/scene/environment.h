// The environment's direction <-> texel mapping on the CPU, the same one shaders/lib/
// environment.glsl uses (tests and the sky generator rely on both agreeing), and its checks.
#pragma once

#include <cstddef>
#include <vector>

#include "scene/scene.h"

namespace penumbra {

// Sizes a map may have: absurd ones are refused before anything is allocated for them.
constexpr int kMaxEnvironmentSide = 16384;
constexpr std::size_t kMaxEnvironmentTexels = std::size_t(1) << 25;  // 8192 x 4096

// Map-local direction of the point (u, v) of the equirectangular map (see EnvironmentMap).
Vec3 environmentDirection(double u, double v);
// The inverse: (u, v) of a map-local unit direction, u in [0, 1), v in [0, 1].
Vec2 environmentUv(Vec3 direction);
// Turns a direction about +y by `radians` (right-handed: +z goes toward +x for positive angles).
Vec3 rotateAboutY(Vec3 v, double radians);

// Radiance seen along world direction `direction` (nearest texel, as the GPU looks it up).
Vec3 environmentRadiance(const Environment& env, Vec3 background, Vec3 direction);

// The radiance a horizontal opening that faces down lets through on average, as irradiance / pi:
// the cosine-weighted mean of the environment over the upper hemisphere (intensity included,
// rotation irrelevant). What the light BVH counts for a sky portal (Material::skyPortal).
Vec3 skyPortalRadiance(const Environment& env, Vec3 background);

// The environment's own lights (the sky's sun) in world space, rotated and scaled with it; the
// renderer adds them to Scene::lights.
std::vector<Light> distantLights(const Environment& env);

// Throws Error naming the problem: inconsistent or absurd map size, negative or non-finite
// radiance, intensity or rotation.
void validateEnvironment(const Environment& env);

}  // namespace penumbra
