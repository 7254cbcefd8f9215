// Combining scenes: what a scene file does with its assets.
#pragma once

#include "core/transform.h"
#include "scene/scene.h"

namespace penumbra {

// Appends `part` to `into` with `transform` applied to its geometry and lights; material and
// texture indices are renumbered. Mirroring transforms keep front faces in front.
void appendScene(Scene& into, Scene part, const Affine& transform);

}  // namespace penumbra
