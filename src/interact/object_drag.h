// Dragging the selected instance with the mouse (docs/VIEWER.md): the point grabbed under the
// cursor moves in the plane facing the camera at its own depth, so it stays under the cursor
// wherever the cursor goes and however the camera moves meanwhile; with Shift held, the drag
// turns the instance about the vertical through its centre instead. Pure math: no window, no GPU.
#pragma once

#include <cstdint>
#include <optional>

#include "core/transform.h"
#include "render/scene_arrays.h"
#include "scene/scene.h"

namespace penumbra::viewer {

struct ObjectDrag {
    std::uint32_t instance = 0;  // Scene::instances
    Vec3 grabbedLocal{0};        // the grabbed point in the instance's object space
    // A turning drag (Shift held at the press): the cursor's x when the instance was last turned,
    // and the centre it turns about (object space).
    bool turning = false;
    float turnedAtX = 0;
    Vec3 centreLocal{0};
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

// Turning by a drag: the angle for a horizontal cursor motion of dxPixels in a window `width`
// pixels wide. A drag across the whole window is one full turn, at any window size; a drag to
// the right turns the side facing the camera to the right (as if the cursor pushed it; seen from
// above, counter-clockwise), so dragging back turns it back.
inline constexpr float kTurnDegreesPerWindowWidth = 360.0f;
float dragTurnDegrees(float dxPixels, std::uint32_t width);

// The move (moveInstance's offset and yaw) that turns an instance placed by objectToWorld by
// yawDegrees about the vertical (world +y) through its object-space point centreLocal, which
// therefore stays where it is. moveInstance turns about the instance's origin; the offset moves
// the origin around the centre.
struct InstanceTurn {
    Vec3 offset{0};
    float yawDegrees = 0;
};
InstanceTurn turnAboutCentre(const Affine& objectToWorld, Vec3 centreLocal, float yawDegrees);

// The centre of a prototype's bounding box in object space (the origin for an empty one): what a
// turning drag turns about.
Vec3 prototypeCentre(const Scene& scene, std::uint32_t prototype);

// A left press at (x, y) of a width x height view: grabs `selected` when it is the instance
// under the cursor (the CPU pick a click makes), to move it or, `turning`, to turn it.
std::optional<ObjectDrag> grabInstance(const Scene& scene, const SceneArrays& arrays, const Camera& camera,
                                       std::uint32_t width, std::uint32_t height, float x, float y,
                                       std::uint32_t selected, bool turning);

// The cursor at (x, y) during a drag: moves the grabbed instance so the grabbed point is under
// the cursor again, or turns it by the cursor's horizontal motion since it last turned. True
// when the instance moved.
bool followCursor(ObjectDrag& drag, Scene& scene, const Camera& camera, std::uint32_t width, std::uint32_t height,
                  float x, float y);

}  // namespace penumbra::viewer
