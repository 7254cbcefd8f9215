// Picking the objects a viewer user can edit (scene/objects.h) in an image: the pixel-centre ray
// traced on the CPU over the host arrays, so it needs no read-back from the GPU.
#pragma once

#include <cstdint>
#include <string>

#include "render/scene_arrays.h"
#include "scene/objects.h"
#include "scene/scene.h"

namespace penumbra {

// What the pixel-centre primary ray of pixel (x, y) hits: the same ray gbuffer.comp traces.
struct Pick {
    std::uint32_t object = kNoObject;      // kNoObject: a miss, or a light sphere
    std::uint32_t primitive = PN_NO_HIT;   // leaf-order index into the arrays
    std::uint32_t material = 0;            // the hit primitive's material (valid when primitive is)
    float depth = 0;                       // linear depth along the view direction (0: miss)
    std::uint32_t instance = kNoObject;    // the scene's instance hit (Scene::instances), if any
};
// The unit direction of the primary ray through window position (x, y) of a width x height image
// (row 0 at the top; no rounding to the pixel centre): cameraRayDirection in shaders/lib/camera.glsl.
Vec3 pixelRayDirection(const Camera& camera, std::uint32_t width, std::uint32_t height, float x, float y);

// x, y: pixel coordinates of a width x height image, row 0 at the top (fractions allowed; the
// ray goes through the centre of the pixel that contains the point). Alpha-tested holes are
// ignored: a click on a cut-out picks the surface it cuts.
Pick pickPixel(const SceneArrays& arrays, const Camera& camera, std::uint32_t width, std::uint32_t height, float x,
               float y);

}  // namespace penumbra
