#include "scene/presets/mesh_builder.h"
#include "scene/presets/presets.h"

namespace penumbra {

Scene makeFurnace(float albedo, Vec3 emission) {
    Scene scene;
    scene.name = "furnace";
    std::uint32_t wall = addMaterial(scene, "wall", Vec3{albedo}, emission);
    Mesh box;
    box.name = "box";
    box.material = wall;
    // A unit cube; every quad is wound so its front (emitting) face points inward.
    const Vec3 p[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                       {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    addQuad(box, p[0], p[1], p[2], p[3]);  // z = -1, faces +z
    addQuad(box, p[5], p[4], p[7], p[6]);  // z = +1, faces -z
    addQuad(box, p[4], p[0], p[3], p[7]);  // x = -1, faces +x
    addQuad(box, p[1], p[5], p[6], p[2]);  // x = +1, faces -x
    addQuad(box, p[4], p[5], p[1], p[0]);  // y = -1, faces +y
    addQuad(box, p[3], p[2], p[6], p[7]);  // y = +1, faces -y
    scene.meshes.push_back(std::move(box));
    scene.camera.position = {0, 0, 0.5f};
    scene.camera.lookAt = {0.2f, -0.1f, -1};
    scene.camera.fovYDegrees = 90.0f;
    return scene;
}

}  // namespace penumbra
