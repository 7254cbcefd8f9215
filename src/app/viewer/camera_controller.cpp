#include "app/viewer/camera_controller.h"

#include <algorithm>
#include <cmath>

namespace penumbra::viewer {
namespace {

constexpr float kTurnRate = 1.5f;        // radians per second for Q/E
constexpr float kMouseRadians = 0.003f;  // per pixel of drag
constexpr float kFastFactor = 4.0f;
constexpr float kMaxPitch = 1.55f;       // just short of straight up or down, where yaw is undefined

}  // namespace

CameraController::CameraController(const Camera& start, float speed) : start_(start), startSpeed_(speed), speed_(speed) {
    setFrom(start);
}

void CameraController::setFrom(const Camera& c) {
    worldUp_ = normalize(c.up);
    position_ = c.position;
    Vec3 forward = normalize(c.lookAt - c.position);
    // A horizontal basis: yaw 0 is the starting direction's horizontal part.
    Vec3 horizontal = forward - worldUp_ * dot(forward, worldUp_);
    if (length(horizontal) < 1e-6f) horizontal = normalize(cross(worldUp_, Vec3{1, 0, 0}));
    yawZero_ = normalize(horizontal);
    yawNinety_ = cross(worldUp_, yawZero_);
    yaw_ = 0;
    pitch_ = std::asin(std::clamp(dot(forward, worldUp_), -1.0f, 1.0f));
    pitch_ = std::clamp(pitch_, -kMaxPitch, kMaxPitch);
}

void CameraController::reset() {
    setFrom(start_);
    speed_ = startSpeed_;
}

void CameraController::scaleSpeed(float factor) { speed_ = std::clamp(speed_ * factor, 1e-4f, 1e6f); }

Camera CameraController::camera() const {
    Vec3 horizontal = yawZero_ * std::cos(yaw_) + yawNinety_ * std::sin(yaw_);
    Vec3 forward = horizontal * std::cos(pitch_) + worldUp_ * std::sin(pitch_);
    Camera c = start_;
    c.position = position_;
    c.lookAt = position_ + forward;
    c.up = worldUp_;
    return c;
}

void CameraController::update(const CameraInput& in, float seconds) {
    // Turning left (Q, mouse left) increases yaw toward yawNinety_ = up x forward, the left side.
    yaw_ += (in.turn * kTurnRate * seconds) - in.lookX * kMouseRadians;
    pitch_ = std::clamp(pitch_ - in.lookY * kMouseRadians, -kMaxPitch, kMaxPitch);
    Camera c = camera();
    Vec3 forward = normalize(c.lookAt - c.position);
    Vec3 right = normalize(cross(forward, worldUp_));
    float step = speed_ * seconds * (in.fast ? kFastFactor : 1.0f);
    position_ = position_ + (forward * in.forward + right * in.right + worldUp_ * in.up) * step;
}

}  // namespace penumbra::viewer
