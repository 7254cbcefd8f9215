// Dragging the selected instance with the mouse (docs/VIEWER.md): the point grabbed under the
// cursor moves in the plane facing the camera at its own depth, so it stays under the cursor
// wherever the cursor goes and however the camera moves meanwhile. Pure math: no window, no GPU.
#pragma once

#include <cstdint>
#include <optional>

#include "core/transform.h"
#include "scene/scene.h"

namespace penumbra::viewer {

struct ObjectDrag {
    std::uint32_t instance = 0;  // Scene::instances
    Vec3 grabbedLocal{0};        // the grabbed point in the instance's object space
};

// Starts a drag of `instance` (placed by objectToWorld) at window position (x, y) of a
// width x height window, where the surface under the cursor lies at linear depth `depth` (a
// Pick's). Nothing when there is no surface (depth <= 0).
std::optional<ObjectDrag> startObjectDrag(std::uint32_t instance, const Affine& objectToWorld, const Camera& camera,
                                          std::uint32_t width, std::uint32_t height, float x, float y, float depth);

// The world offset that brings `grabbed` (a world point) under window position (x, y) at the
// linear depth (distance along the view direction) it has now: the move in the plane facing the
// camera. Zero when the point is not in front of the camera.
Vec3 dragOffset(const Camera& camera, std::uint32_t width, std::uint32_t height, Vec3 grabbed, float x, float y);

}  // namespace penumbra::viewer
