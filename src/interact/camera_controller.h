// First-person camera control: yaw/pitch plus a position, moved by keys and mouse, either in free
// flight or, on levels with a walk map (Doom), walking with Doom's collision (scene/walk/). No
// GLFW here (the app feeds it input), so the arithmetic is testable without a window.
#pragma once

#include <optional>

#include "scene/scene.h"
#include "scene/walk/walk_physics.h"

namespace penumbra::viewer {

struct CameraInput {
    float forward = 0, right = 0, up = 0;  // -1..1 from WASD, Space/C (up: flight only)
    float turn = 0;                        // -1..1 from Q/E (radians per second scale below)
    float lookX = 0, lookY = 0;            // pointer pixels moved while looking (captured or dragging)
    bool fast = false;                     // Shift: 4x in flight, Doom's run when walking
};

class CameraController {
public:
    // speed: metres per second in flight (the app derives it from the scene's size). With a walk
    // map the controller starts walking when the start camera is a place the player fits.
    CameraController(const Camera& start, float speed, std::optional<walk::WalkMap> walkMap = std::nullopt);

    void update(const CameraInput& input, float seconds);
    void scaleSpeed(float factor);  // scroll wheel (flight speed)
    void reset();                   // back to the starting camera and speed

    // Walking on or off. Turning it on fails (false, still flying) without a walk map or where
    // the player does not fit (inside a wall, outside the map).
    bool setWalking(bool on);
    bool walking() const { return walking_; }
    bool canWalk() const { return walkMap_.has_value(); }

    Camera camera() const;
    // Walking: the player (map units). Its level's sectors move: the heights walking meets now.
    const walk::WalkState& player() const { return player_; }
    void setSectorHeights(const std::vector<walk::WalkSector>& sectors);
    float speed() const { return speed_; }

private:
    void setFrom(const Camera& c);
    void fly(const CameraInput& in, float seconds);
    void walk(const CameraInput& in, float seconds);
    Vec3 horizontalForward() const;

    Camera start_;
    float startSpeed_;
    Vec3 worldUp_;
    Vec3 position_;
    float yaw_ = 0, pitch_ = 0;  // radians; yaw about worldUp_, pitch up from the horizon
    Vec3 yawZero_, yawNinety_;   // horizontal basis the yaw angle is measured in
    float speed_;
    std::optional<walk::WalkMap> walkMap_;
    bool walking_ = false;
    walk::WalkState player_;
    double eyeLag_ = 0;  // map units the eye trails the feet after a step up (Doom's view height)
};

}  // namespace penumbra::viewer
