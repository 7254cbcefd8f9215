// The objects a viewer user can pick and edit: each mesh, then each of the scene's own spheres
// (the spheres made for sphere lights are lights, not objects). Scene data only; picking them in
// an image is render/picking.h.
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace penumbra {

inline constexpr std::uint32_t kNoObject = 0xffffffffu;

std::uint32_t sphereObject(const Scene& scene, std::size_t sphere);
bool isObject(const Scene& scene, std::uint32_t object);
std::string objectName(const Scene& scene, std::uint32_t object);  // "mesh 'floor'", "sphere 2"
std::uint32_t objectMaterial(const Scene& scene, std::uint32_t object);
// Moves a mesh's vertices or a sphere's centre by offset (the caller rebuilds the GPU scene).
void translateObject(Scene& scene, std::uint32_t object, Vec3 offset);

// Instances are edited by their transform alone (the renderer then rebuilds only its top level).
// The instance's name: its prototype's, with its number ("instance 3 (bunny.obj)").
std::string instanceName(const Scene& scene, std::uint32_t instance);
// Turns instance `instance` by yawDegrees about the vertical through its origin, then moves it by
// offset (world space). An animated instance keeps the move as its user edit (InstanceAnimation::
// userEdit), so its animation plays on from the moved place instead of undoing the move.
void moveInstance(Scene& scene, std::uint32_t instance, Vec3 offset, float yawDegrees);

}  // namespace penumbra
