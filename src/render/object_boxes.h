// The boxes of --accel objects (shared/accel_layouts.h ObjectBox, walked by
// shaders/lib/object_boxes.glsl): a flat scene gets one box per scene object (a mesh, a sphere;
// primitives of no object, such as light spheres and sprites, share one more box); a two-level
// scene splits the world's own geometry (its identity instance) the same way and gives each scene
// instance one box.
#pragma once

#include "render/scene_arrays.h"

namespace penumbra {

// Fills arrays.objectBoxes and arrays.objectPrims from the arrays' primitives, primitiveObject and
// (two levels) top-level leaves. Boxes are exact for triangles and spheres; a sprite counts with
// its BVH leaf's box.
void buildObjectBoxes(SceneArrays& arrays);

}  // namespace penumbra
