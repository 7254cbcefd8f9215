// The scene at a moment. Everything that changes over time goes through here: today the camera
// path of a scene file (and the torch carried with that camera); later, animated nodes and
// textures. `penumbra render --time T` and image sequences (--frames) render the scene this
// function makes, so a new kind of animation only has to teach this file.
#pragma once

#include "scene/scene.h"

namespace penumbra {

// Moves `scene` to `seconds` in place: animated nodes' instances (Scene::instanceAnimations) to
// their transforms then, the camera onto its path (position, look-at and field of view; up, lens
// and focus stay), and a torch attached to the camera along with it.
void applySceneTime(Scene& scene, double seconds);

// Only the instances: each animated instance (glTF animations, scene-file motions) to its
// transform at `seconds`. The viewer's clock uses it; its camera is the user's.
void applyInstanceAnimations(Scene& scene, double seconds);

// A copy of `scene` at `seconds` (applySceneTime on a copy).
Scene sceneAtTime(const Scene& scene, double seconds);

// Whether anything in the scene changes over time.
bool isAnimated(const Scene& scene);
// Whether moving to another moment changes more than the camera and the lights carried with it
// (the top-level BVH would have to be rebuilt): true when nodes are animated.
bool animatesGeometry(const Scene& scene);

// The camera of `path` at `seconds`, keeping base's up, lens and focus. Before the first key it
// stands at the first, after the last at the last. Catmull-Rom: the cubic Hermite curve through
// the keys whose tangents are central differences over time (one-sided at the ends), so uneven
// key spacing keeps the speed smooth; Linear: straight segments at constant speed.
Camera cameraOnPath(const CameraPath& path, const Camera& base, double seconds);

// Checks a path: keys finite, times strictly increasing, no key looking at its own position.
// Throws Error naming the key.
void validateCameraPath(const CameraPath& path);

}  // namespace penumbra
