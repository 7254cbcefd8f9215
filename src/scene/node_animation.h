// Node animation (glTF animations): keyframed translation, rotation and scale of the nodes above
// an instance, sampled at a moment to give the instance's transform. scene/animation.h applies it
// (applySceneTime), so `render --time T` and sequences show the moment T.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/transform.h"
#include "core/vec.h"
#include "scene/object_motion.h"

namespace penumbra {

enum class KeyInterpolation { Step, Linear, CubicSpline };

using KeyValue = std::array<float, 4>;  // xyz (translation, scale) or a quaternion xyzw (rotation)

// One animated property of a node.
struct Track {
    std::vector<float> times;  // seconds, strictly increasing; empty: not animated
    // One per key; CubicSpline: three per key (in-tangent, value, out-tangent), as glTF stores them.
    std::vector<KeyValue> values;
    KeyInterpolation interpolation = KeyInterpolation::Linear;

    bool present() const { return !times.empty(); }
};

// A node on the way from a root to an animated instance: a fixed local transform, or one made of
// translation, rotation and scale (glTF's TRS), each at rest or following its track, or a scene
// file's motion moving the fixed transform (motionTransform).
struct NodeMotion {
    bool trs = false;
    Affine fixed;  // !trs (with `scripted`: the placement it moves)
    std::optional<ScriptedMotion> scripted;  // !trs
    Vec3 translation{0};
    KeyValue rotation{0, 0, 0, 1};  // unit quaternion xyzw
    Vec3 scale{1};
    Track translationTrack, rotationTrack, scaleTrack;
};

// Scene::instances[instance] is the product of its chain's local transforms (root first), with
// the user's edit (the viewer's moves, scene/objects.h) composed on top: see editedTransform.
struct InstanceAnimation {
    std::uint32_t instance = 0;
    std::vector<NodeMotion> chain;
    Affine userEdit;  // identity until the user moves the instance
};

// An animated transform with a user's edit on top: the animated origin moved by the edit's
// translation (world space) and the animated linear part turned by the edit's linear part about
// that origin. So an edited object keeps its animation, displaced and turned: a patrol walks the
// same path one metre to the left, a spinning object keeps spinning about its own (moved) origin.
// Edits compose: editedTransform(b, editedTransform(a, t)) == editedTransform(composeEdits(b, a), t).
Affine editedTransform(const Affine& edit, const Affine& animated);
Affine composeEdits(const Affine& later, const Affine& earlier);

// The track's value at `seconds`: the first key's before it, the last key's after; quaternions
// (rotation) interpolate along the shorter arc (slerp) and come back unit length.
KeyValue sampleTrack(const Track& track, double seconds, bool quaternion);

// translation * rotation * scale, the glTF order.
Affine trsTransform(Vec3 translation, const KeyValue& rotation, Vec3 scale);

// The chain's transform at `seconds`.
Affine chainTransform(const std::vector<NodeMotion>& chain, double seconds);

// Throws Error naming `where` when a track's times are not finite and strictly increasing or its
// value count does not match them.
void validateTrack(const Track& track, const std::string& where);

}  // namespace penumbra
