// Adding a model to the open scene (scene/add_model.h): it becomes one prototype placed once in
// front of the camera, whole in the view, its triangles hit by the pixel-centre ray through the
// image's middle (the viewer's CPU pick), and it moves and turns as an instance.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "render/gpu_scene.h"
#include "render/picking.h"
#include "scene/add_model.h"
#include "scene/objects.h"
#include "scene/presets/mesh_builder.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

constexpr std::uint32_t kW = 64, kH = 48;

// A cube of side `side` centred at `centre`, one red material (its units are the file's).
Scene cubeModel(float side, Vec3 centre) {
    Scene m;
    m.name = "cube.obj";
    const std::uint32_t red = addMaterial(m, "red", {0.8f, 0.1f, 0.1f});
    Mesh cube;
    cube.name = "cube";
    cube.material = red;
    const float h = side / 2;
    auto p = [&](float x, float y, float z) { return centre + Vec3{x, y, z} * h; };
    addQuad(cube, p(-1, -1, 1), p(1, -1, 1), p(1, 1, 1), p(-1, 1, 1));
    addQuad(cube, p(1, -1, -1), p(-1, -1, -1), p(-1, 1, -1), p(1, 1, -1));
    addQuad(cube, p(-1, -1, -1), p(-1, -1, 1), p(-1, 1, 1), p(-1, 1, -1));
    addQuad(cube, p(1, -1, 1), p(1, -1, -1), p(1, 1, -1), p(1, 1, 1));
    addQuad(cube, p(-1, 1, 1), p(1, 1, 1), p(1, 1, -1), p(-1, 1, -1));
    addQuad(cube, p(-1, -1, -1), p(1, -1, -1), p(1, -1, 1), p(-1, -1, 1));
    m.meshes.push_back(cube);
    return m;
}

TEST(AddModel, TheModelAppearsInFrontOfTheCameraAsAMovableInstance) {
    // Units far from the room's: a 40-unit cube 1000 units away from its origin.
    for (float side : {0.1f, 40.0f}) {
        Scene scene = makeCornellBox();
        const Camera camera = scene.camera;
        const std::size_t materials = scene.materials.size();
        const Pick before = pickPixel(buildSceneArrays(scene), camera, kW, kH, kW / 2.0f, kH / 2.0f);
        EXPECT_EQ(before.instance, kNoObject);

        // The viewer's free room ahead: half the depth of the surface in the middle of the view.
        const AddedModel added = addModelInFront(scene, cubeModel(side, {1000, -500, 3}), camera, 0.5f * before.depth);
        ASSERT_NO_THROW(scene.validate());
        EXPECT_EQ(added.prototype, scene.prototypes.size() - 1);
        EXPECT_EQ(added.instance, scene.instances.size() - 1);
        EXPECT_EQ(scene.prototypes[added.prototype].name, "cube.obj");
        ASSERT_EQ(scene.materials.size(), materials + 1);
        EXPECT_EQ(scene.materials.back().name, "red");
        EXPECT_EQ(scene.prototypes[added.prototype].meshes[0].material, materials);

        // Its triangles are what the middle of the view now sees, in front of the back wall.
        const SceneArrays arrays = buildSceneArrays(scene);
        const Pick after = pickPixel(arrays, camera, kW, kH, kW / 2.0f, kH / 2.0f);
        EXPECT_EQ(after.instance, added.instance) << "side " << side;
        EXPECT_EQ(after.material, materials);
        EXPECT_LT(after.depth, before.depth);
        // Whole in the view: the image's border pixels still see the room.
        for (std::uint32_t x = 0; x < kW; x += 4)
            for (float y : {0.5f, kH - 0.5f})
                EXPECT_NE(pickPixel(arrays, camera, kW, kH, float(x) + 0.5f, y).instance, added.instance);

        // Only a model too big for the room is scaled (to fit in front of the back wall).
        const float scale = std::cbrt(std::abs(scene.instances[added.instance].transform.determinant()));
        if (side < 1) EXPECT_FLOAT_EQ(scale, 1.0f);
        else EXPECT_LT(scale * side, 0.5f);
        // It moves like any instance: to the side, and the middle sees the room again.
        moveInstance(scene, added.instance, {1.0f, 0, 0}, 30.0f);
        EXPECT_EQ(pickPixel(buildSceneArrays(scene), camera, kW, kH, kW / 2.0f, kH / 2.0f).instance, kNoObject);
    }
}

TEST(AddModel, AModelWithoutTrianglesIsRefusedAndTheSceneKept) {
    Scene scene = makeCornellBox();
    const std::size_t prototypes = scene.prototypes.size(), materials = scene.materials.size();
    Scene empty;
    empty.name = "points.obj";
    empty.materials.push_back({"m", Vec3{0.5f}});
    EXPECT_THROW(addModelInFront(scene, empty, scene.camera), Error);
    EXPECT_EQ(scene.prototypes.size(), prototypes);
    EXPECT_EQ(scene.materials.size(), materials);
}

}  // namespace
}  // namespace penumbra
