#include "interact/grid_walk.h"

#include <cmath>
#include <limits>

namespace penumbra::viewer {
namespace {

constexpr float kQuarter = 1.5707963f;
constexpr float kPi = 3.14159265f;

// The horizontal direction of facing f (quarter turns left from -z).
Vec3 directionOf(float yaw) { return {-std::sin(yaw), 0, -std::cos(yaw)}; }

float smoothstep(float t) { return t * t * (3.0f - 2.0f * t); }

}  // namespace

GridWalker::GridWalker(const TileGrid& grid, const Camera& start) : grid_(grid), base_(start) {
    const float fx = (start.position.x - grid.origin.x) / grid.tileSize;
    const float fz = (start.position.z - grid.origin.z) / grid.tileSize;
    float best = std::numeric_limits<float>::max();
    for (int z = 0; z < grid.depth; ++z)
        for (int x = 0; x < grid.width; ++x) {
            const float d = std::hypot(float(x) + 0.5f - fx, float(z) + 0.5f - fz);
            if (grid.canStand(x, z) && d < best) best = d, x_ = x, z_ = z;
        }
    const Vec3 view = start.lookAt - start.position;
    const float yaw = std::atan2(-view.x, -view.z);  // inverse of directionOf
    facing_ = ((int(std::lround(yaw / kQuarter)) % 4) + 4) % 4;
    fromEye_ = eyeAt(x_, z_);
    fromYaw_ = float(facing_) * kQuarter;
}

Vec3 GridWalker::eyeAt(int x, int z) const {
    return grid_.origin + Vec3{(float(x) + 0.5f) * grid_.tileSize, grid_.eyeHeight, (float(z) + 0.5f) * grid_.tileSize};
}

void GridWalker::update(const CameraInput& in, float seconds) {
    if (progress_ < 1.0f) {
        progress_ = std::min(1.0f, progress_ + seconds / kStepSeconds);
        return;
    }
    const int turn = in.turn > 0 ? 1 : in.turn < 0 ? -1 : 0;
    const int ahead = in.forward > 0 ? 1 : in.forward < 0 ? -1 : 0;
    const int side = in.right > 0 ? 1 : in.right < 0 ? -1 : 0;
    if (turn == 0 && ahead == 0 && side == 0) return;
    fromEye_ = eyeAt(x_, z_);
    fromYaw_ = float(facing_) * kQuarter;
    moving_ = turn == 0;
    if (turn != 0) {
        facing_ = (facing_ + turn + 4) % 4;
        // Turning the short way round from 3 to 0 and back: the start yaw moves by a full turn.
        if (facing_ == 0 && turn > 0) fromYaw_ -= 4 * kQuarter;
        if (facing_ == 3 && turn < 0) fromYaw_ += 4 * kQuarter;
    } else {
        const Vec3 f = directionOf(float(facing_) * kQuarter);
        const Vec3 r{-f.z, 0, f.x};  // f turned a quarter to the right
        const int dx = int(std::lround(f.x)) * ahead + int(std::lround(r.x)) * side;
        const int dz = int(std::lround(f.z)) * ahead + int(std::lround(r.z)) * side;
        if (!grid_.canStand(x_ + dx, z_ + dz)) return;  // a wall: no step
        x_ += dx;
        z_ += dz;
    }
    progress_ = 0.0f;
}

Camera GridWalker::camera() const {
    const float t = smoothstep(progress_);
    const Vec3 to = eyeAt(x_, z_);
    const float toYaw = float(facing_) * kQuarter;
    Camera c = base_;
    c.position = fromEye_ + (to - fromEye_) * t;
    if (moving_ && progress_ < 1.0f) c.position.y += kBobFraction * grid_.tileSize * std::sin(kPi * progress_);
    c.lookAt = c.position + directionOf(fromYaw_ + (toYaw - fromYaw_) * t);
    c.up = Vec3{0, 1, 0};
    return c;
}

}  // namespace penumbra::viewer
