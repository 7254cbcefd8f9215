// Dragging a sphere group (the caffeine molecule, scene/sphere_groups.h) with the mouse, as an
// instance is dragged (object_drag.h): the grabbed point follows the cursor in the plane facing
// the camera at its depth, or with Shift held the group turns about the vertical through its
// pivot. The group's spheres are world data, so each step moves their centres and the caller
// rebuilds the GPU scene. Pure math: no window, no GPU.
#pragma once

#include <cstdint>
#include <optional>

#include "render/scene_arrays.h"
#include "scene/scene.h"

namespace penumbra::viewer {

struct GroupDrag {
    std::uint32_t group = 0;  // Scene::sphereGroups
    Vec3 grabbedFromPivot{0};  // the grabbed point, relative to the group's pivot (world axes)
    bool turning = false;
    float turnedAtX = 0;       // the cursor's x when the group last turned
};

// A left press at (x, y) of a width x height view: grabs group `selected` when one of its spheres
// is under the cursor (the CPU pick a click makes); `turning` to turn it.
std::optional<GroupDrag> grabSphereGroup(const Scene& scene, const SceneArrays& arrays, const Camera& camera,
                                         std::uint32_t width, std::uint32_t height, float x, float y,
                                         std::uint32_t selected, bool turning);

// The cursor at (x, y) during a drag: moves or turns the group. True when it changed.
bool followCursor(GroupDrag& drag, Scene& scene, const Camera& camera, std::uint32_t width, std::uint32_t height,
                  float x, float y);

}  // namespace penumbra::viewer
