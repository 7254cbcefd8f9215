// Grid movement on a tile-map level (Scene::tileGrid, the dungeon): one tile per step forward,
// back or sideways, a quarter turn per turn, each animated over a short step so the view glides
// instead of jumping, as in the dungeon crawlers the WebGPU renderer's scene imitates. No GLFW
// here (the app feeds it input), so it is testable without a window.
#pragma once

#include "interact/camera_controller.h"
#include "scene/scene.h"

namespace penumbra::viewer {

class GridWalker {
public:
    static constexpr float kStepSeconds = 0.18f;
    // Head bob: a step forward, back or sideways lifts the eye by up to this fraction of a tile
    // and sets it down again (half a sine over the step; turns do not bob). The WebGPU renderer's
    // is 0.06 m on 2 m tiles over its 0.25 s step.
    static constexpr float kBobFraction = 0.03f;

    // Starts on the tile under `start` (or the nearest walkable one), facing the axis closest to
    // its view direction.
    GridWalker(const TileGrid& grid, const Camera& start);

    // Held keys start the next step once the last one has finished: forward/back and right
    // (strafe) move one tile when it is walkable, turn a quarter turn (positive: left).
    void update(const CameraInput& input, float seconds);
    Camera camera() const;
    bool stepping() const { return progress_ < 1.0f; }
    int tileX() const { return x_; }
    int tileZ() const { return z_; }
    int facing() const { return facing_; }  // 0: -z (north), 1: -x, 2: +z, 3: +x (quarter turns left)

private:
    Vec3 eyeAt(int x, int z) const;
    TileGrid grid_;
    Camera base_;
    int x_ = 0, z_ = 0, facing_ = 0;
    Vec3 fromEye_;
    float fromYaw_ = 0;       // radians, of the pose the step started from
    float progress_ = 1.0f;  // of the current step, [0, 1]
    bool moving_ = false;    // the current step goes to another tile (a turn: false)
};

}  // namespace penumbra::viewer
