// Scene-file motions ("motion" on an asset or an instance, docs/SCENES.md): an object travelling
// along a path of offsets at a constant speed, and spinning about an axis through its own origin.
// A motion is one node of an instance's animation chain (node_animation.h), so scene/animation.h
// plays it with glTF animations: `render --time T`, sequences and the viewer.
#pragma once

#include <string>
#include <vector>

#include "core/transform.h"
#include "core/vec.h"

namespace penumbra {

// What the object does once it reaches the path's last point.
enum class MotionRepeat {
    Loop,          // on to the first point and around again (a closed path)
    BackAndForth,  // back along the path to the first point, and again (a patrol)
    Once,          // stops at the last point
};

struct ScriptedMotion {
    std::vector<Vec3> path;  // offsets in metres, in the parent's frame; fewer than two: no travel
    float speed = 1.0f;      // metres per second along the path, > 0
    MotionRepeat repeat = MotionRepeat::Loop;
    Vec3 spinAxis{0, 1, 0};          // unit, in the object's own coordinates
    float spinDegreesPerSecond = 0;  // right-handed about spinAxis
};

// The path's offset `seconds` after time 0 (at time 0 and before: the first point).
Vec3 pathOffset(const ScriptedMotion& motion, double seconds);

// The node's local transform at `seconds`: placement moved by pathOffset, spun first about the
// object's own origin: translation(offset) * placement * rotation(spin).
Affine motionTransform(const ScriptedMotion& motion, const Affine& placement, double seconds);

// Throws Error naming `where` when a point, the speed or the spin is not finite, the speed is not
// positive or the spin axis has no length.
void validateMotion(const ScriptedMotion& motion, const std::string& where);

}  // namespace penumbra
