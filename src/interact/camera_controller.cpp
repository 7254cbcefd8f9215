#include "interact/camera_controller.h"

#include <algorithm>
#include <cmath>

#include "scene/io/wad/units.h"

namespace penumbra::viewer {
namespace {

constexpr float kTurnRate = 1.5f;        // radians per second for Q/E
constexpr float kMouseRadians = 0.003f;  // per pixel of drag
constexpr float kFastFactor = 4.0f;
constexpr float kMaxPitch = 1.55f;       // just short of straight up or down, where yaw is undefined
// After a step up the eye catches up with the feet in about 8 tics, as Doom's view height does.
constexpr double kEyeCatchUpRate = 35.0 / 8.0;  // per second

}  // namespace

CameraController::CameraController(const Camera& start, float speed, std::optional<walk::WalkMap> walkMap)
    : start_(start), startSpeed_(speed), speed_(speed), walkMap_(std::move(walkMap)) {
    setFrom(start);
    setWalking(true);
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
    const bool wasWalking = walking_;
    walking_ = false;
    setFrom(start_);
    speed_ = startSpeed_;
    if (wasWalking) setWalking(true);
}

bool CameraController::setWalking(bool on) {
    if (!on || !walkMap_) {
        walking_ = false;
        return !on;
    }
    // The eye is kEyeHeight above the feet; the player is placed between floor and ceiling.
    const Vec3 eye = wad::sceneToMap(position_);
    std::optional<walk::WalkState> placed = walk::placePlayer(*walkMap_, eye.x, eye.y, eye.z - walk::kEyeHeight);
    if (!placed) return false;
    player_ = *placed;
    eyeLag_ = 0;
    walking_ = true;
    position_ = wad::mapToScene(player_.x, player_.y, player_.z + walk::kEyeHeight);
    return true;
}

void CameraController::setSectorHeights(const std::vector<walk::WalkSector>& sectors) {
    if (walkMap_ && walkMap_->sectors.size() == sectors.size()) walkMap_->sectors = sectors;
}

void CameraController::scaleSpeed(float factor) { speed_ = std::clamp(speed_ * factor, 1e-4f, 1e6f); }

Vec3 CameraController::horizontalForward() const { return yawZero_ * std::cos(yaw_) + yawNinety_ * std::sin(yaw_); }

Camera CameraController::camera() const {
    Vec3 forward = horizontalForward() * std::cos(pitch_) + worldUp_ * std::sin(pitch_);
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
    if (walking_) walk(in, seconds);
    else fly(in, seconds);
}

void CameraController::fly(const CameraInput& in, float seconds) {
    Camera c = camera();
    Vec3 forward = normalize(c.lookAt - c.position);
    Vec3 right = normalize(cross(forward, worldUp_));
    float step = speed_ * seconds * (in.fast ? kFastFactor : 1.0f);
    position_ = position_ + (forward * in.forward + right * in.right + worldUp_ * in.up) * step;
}

void CameraController::walk(const CameraInput& in, float seconds) {
    // Moves follow the view's heading only (looking down does not slow the walk), at Doom's
    // walking or running speed, never faster on a diagonal.
    const Vec3 forward = horizontalForward();
    const Vec3 right = normalize(cross(forward, worldUp_));
    Vec3 wish = forward * in.forward + right * in.right;
    if (length(wish) > 1.0f) wish = normalize(wish);
    const double speed = in.fast ? walk::kRunSpeed : walk::kWalkSpeed;  // map units/s
    const Vec3 velocity = wad::sceneToMap(wish * float(speed / wad::kUnitsPerMetre));
    const double before = player_.z;
    player_ = walk::stepWalk(*walkMap_, player_, velocity.x, velocity.y, seconds);
    if (player_.z > before && player_.vz == 0) eyeLag_ -= player_.z - before;  // stepped up
    eyeLag_ *= std::exp(-kEyeCatchUpRate * double(std::max(seconds, 0.0f)));
    if (eyeLag_ > -0.01) eyeLag_ = 0;
    position_ = wad::mapToScene(player_.x, player_.y, player_.z + walk::kEyeHeight + eyeLag_);
}

}  // namespace penumbra::viewer
