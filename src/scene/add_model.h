// Adding a model to the open scene (the viewer's Add model field and M key, docs/VIEWER.md): the
// model becomes one new prototype placed once, in front of the camera, so the viewer can select,
// drag and turn it like any instance. Scene data only: the caller rebuilds the GPU scene once.
#pragma once

#include <cstdint>
#include <limits>

#include "scene/scene.h"

namespace penumbra {

struct AddedModel {
    std::uint32_t prototype = 0;
    std::uint32_t instance = 0;
};

// Adds `model`'s triangles (its own instances baked first) with their materials and textures.
// Its lights, spheres and sprites are left out: an instance places meshes only. The prototype's
// object space has the model's bounding-box centre at the origin (what the instance turns about),
// and the instance puts that centre on the camera's view axis at 1.5 times the distance at which
// the model's bounding sphere would just fill the view's height, so it appears whole at its own
// size. When that is beyond `maxDistance` (the caller's free room ahead: the viewer passes half
// the depth of the surface in the middle of the view), the model is scaled down to fit there
// instead, so a model in other units (millimetres in a metre scene) still shows in front of the
// walls. Throws Error when the model has no triangles.
AddedModel addModelInFront(Scene& scene, Scene model, const Camera& camera,
                           float maxDistance = std::numeric_limits<float>::infinity());

}  // namespace penumbra
