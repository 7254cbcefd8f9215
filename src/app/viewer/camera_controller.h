// First-person camera control: yaw/pitch plus a position, moved by keys and mouse. No GLFW here
// (the app feeds it input), so the arithmetic is testable without a window.
#pragma once

#include "scene/scene.h"

namespace penumbra::viewer {

struct CameraInput {
    float forward = 0, right = 0, up = 0;  // -1..1 from WASD, Space/C
    float turn = 0;                        // -1..1 from Q/E (radians per second scale below)
    float lookX = 0, lookY = 0;            // mouse pixels moved with the right button held
    bool fast = false;                     // Shift
};

class CameraController {
public:
    // speed: metres per second (the app derives it from the scene's size).
    CameraController(const Camera& start, float speed);

    void update(const CameraInput& input, float seconds);
    void scaleSpeed(float factor);  // scroll wheel
    void reset();                   // back to the starting camera and speed

    Camera camera() const;
    float speed() const { return speed_; }

private:
    void setFrom(const Camera& c);

    Camera start_;
    float startSpeed_;
    Vec3 worldUp_;
    Vec3 position_;
    float yaw_ = 0, pitch_ = 0;  // radians; yaw about worldUp_, pitch up from the horizon
    Vec3 yawZero_, yawNinety_;   // horizontal basis the yaw angle is measured in
    float speed_;
};

}  // namespace penumbra::viewer
