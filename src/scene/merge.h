// Combining scenes: what a scene file does with its assets.
#pragma once

#include "core/transform.h"
#include "scene/scene.h"

namespace penumbra {

// Appends `part` to `into` with `transform` applied to its geometry and lights; material and
// texture indices are renumbered. Mirroring transforms keep front faces in front.
void appendScene(Scene& into, Scene part, const Affine& transform);

// The factor by which `transform` scales lengths on average: the cube root of |determinant|.
// Exact for uniform scaling; spheres, light radii and camera lenses scale by it.
float meanScale(const Affine& transform);

// The camera that sees the transformed world as `camera` sees the original: position, look-at
// and up move with the world, aperture and focus distance scale with it. A mirroring transform
// gives the mirror image (the camera stays right-handed).
Camera transformCamera(const Camera& camera, const Affine& transform);

}  // namespace penumbra
