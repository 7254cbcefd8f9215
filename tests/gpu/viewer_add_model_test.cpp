// Adding a model in the viewer (scene/add_model.h, then InteractiveRenderer::rebuildScene): the
// picture changes where it was placed (the middle of the view now shows the model's material),
// and moving it as an instance (the top level alone) uncovers the wall behind again.
#include <vector>

#include "gpu_fixture.h"
#include "render/interactive_renderer.h"
#include "scene/add_model.h"
#include "scene/objects.h"
#include "scene/presets/mesh_builder.h"
#include "scene/presets/presets.h"

namespace penumbra::test {
namespace {

using ViewerAddModelTest = GpuTest;

constexpr std::uint32_t kW = 24, kH = 24;

// The surface (material + 1, 0: nothing) the middle pixel's G-buffer shows.
std::uint32_t middleSurface(gpu::Context& ctx, InteractiveRenderer& viewer, const Camera& camera) {
    viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, camera, ViewSettings{}); });
    viewer.finishFrame();
    const auto g = gpu::downloadBuffer<shader::GBufferTexel>(ctx, viewer.commands(), viewer.gbuffer(), kW * kH);
    return g[(kH / 2) * kW + kW / 2].surfaceId;
}

TEST_F(ViewerAddModelTest, TheAddedModelShowsWhereItWasPlacedAndMovesAsAnInstance) {
    Scene scene = makeCornellBox();
    const Camera camera = scene.camera;
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(kW, kH);
    const std::uint32_t wall = middleSurface(*ctx, viewer, camera);
    ASSERT_NE(wall, 0u);

    Scene model;
    model.name = "card";
    const std::uint32_t red = addMaterial(model, "red", {0.9f, 0.1f, 0.1f});
    addQuadMesh(model, "card", red, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0});
    const AddedModel added = addModelInFront(scene, model, camera, 0.5f);
    viewer.rebuildScene(scene, false);
    const std::uint32_t redSurface = std::uint32_t(scene.materials.size());  // the last material, + 1
    EXPECT_EQ(middleSurface(*ctx, viewer, camera), redSurface);

    moveInstance(scene, added.instance, {0.5f, 0, 0}, 0.0f);
    viewer.setInstanceTransforms(scene);
    EXPECT_EQ(middleSurface(*ctx, viewer, camera), wall);
}

}  // namespace
}  // namespace penumbra::test
