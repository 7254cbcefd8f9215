// The rest tree: a flat BVH that stands for a two-level scene while every instance lies where it
// was modelled (a Doom map whose doors and lifts are all at rest), so a still map walks one level
// as it did before its movers became instances. Its leaves are the leaves of the world's BVH and
// of each instance's bottom level, the same primitive slots, with a BVH built over their boxes:
// no primitive is copied, and the tree is built once with the scene and never changes. While an
// instance is away from rest the frame walks the two-level tree as before (render/instance_arrays.h).
#pragma once

#include "render/scene_arrays.h"
#include "shared/frame.h"

namespace penumbra {

// Appends the rest tree to arrays.nodes and sets arrays.restRoot, when the scene has instances
// beside the world's and every one is placed by the identity; call after the bottom levels and
// before the top level (which replaces every node after bottomNodeCount). Not with
// RenderTuning::forceInstances (that measures the two-level walk) or restTree off.
void appendRestTree(SceneArrays& arrays);

// Whether the rest tree may stand for the two-level tree: it exists and every instance is at rest.
bool atRest(const SceneArrays& arrays);

// The frame walks the rest tree as a flat scene: no instances, its root where the walks begin.
void walkRestTree(shader::FrameUniforms& frame, const SceneArrays& arrays);

}  // namespace penumbra
