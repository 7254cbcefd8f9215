// Editing a group of spheres as one rigid object (Scene::sphereGroups: the caffeine molecule):
// the viewer picks any of its spheres and moves or turns them all together. Scene data only; the
// caller rebuilds the GPU scene (spheres live in the one flat BVH, so a move is a rebuild, which
// for a few dozen spheres costs well under a millisecond).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/transform.h"
#include "scene/scene.h"

namespace penumbra {

// The group sphere `sphere` belongs to, if any.
std::optional<std::uint32_t> sphereGroupOf(const Scene& scene, std::size_t sphere);
// "group 'caffeine' (24 spheres)".
std::string sphereGroupName(const Scene& scene, std::uint32_t group);
// What the group turns about: the mean of its spheres' centres (the origin for an empty group).
Vec3 sphereGroupPivot(const Scene& scene, std::uint32_t group);

// Moves every sphere of the group by `offset`.
void moveSphereGroup(Scene& scene, std::uint32_t group, Vec3 offset);
// Turns the group rigidly by `rotation` (its linear part; any translation is ignored) about its
// pivot, which stays where it is. Radii are kept: a rigid turn needs a rotation, which
// Affine::eulerDegrees gives.
void turnSphereGroup(Scene& scene, std::uint32_t group, const Affine& rotation);

}  // namespace penumbra
