// An emitter whose material is alpha tested (glTF MASK): its hole texels let rays through, so
// they emit nothing. Light sampling picks points uniformly over the whole triangle, holes
// included; a point in a hole must bring no light, as the BSDF-sampled ray through it finds
// none. Light sampling only, BSDF sampling only and MIS must then agree on the floor below.
#include "gpu_fixture.h"
#include "render_compare.h"
#include "scene/presets/mesh_builder.h"

namespace penumbra::test {
namespace {

// A 1 m square emitter 1 m above a diffuse floor, facing down; its texture is a 2x2 checker of
// opaque and fully transparent 4x4 blocks, so half of its area is holes. The camera looks at the
// floor and never sees the emitter.
Scene holedEmitterScene() {
    Scene scene;
    scene.name = "holed emitter";
    Texture mask;
    mask.name = "checker mask";
    mask.width = mask.height = 8;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const std::uint8_t alpha = ((x / 4) + (y / 4)) % 2 == 0 ? 255 : 0;
            mask.rgba.insert(mask.rgba.end(), {255, 255, 255, alpha});
        }
    scene.textures.push_back(mask);
    const std::uint32_t floorMaterial = addMaterial(scene, "floor", Vec3{0.5f});
    const std::uint32_t lamp = addMaterial(scene, "lamp", Vec3{1.0f}, Vec3{4.0f});
    scene.materials[lamp].albedoTexture.texture = 0;
    scene.materials[lamp].alphaCutoff = 0.5f;
    Mesh floor;
    floor.name = "floor";
    floor.material = floorMaterial;
    addQuad(floor, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2});
    scene.meshes.push_back(floor);
    Mesh panel;
    panel.name = "lamp";
    panel.material = lamp;
    addQuad(panel, {-0.5f, 1, -0.5f}, {0.5f, 1, -0.5f}, {0.5f, 1, 0.5f}, {-0.5f, 1, 0.5f});  // faces down
    panel.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    scene.meshes.push_back(panel);
    scene.camera.position = {0, 0.6f, 2.2f};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.fovYDegrees = 40;
    return scene;
}

SampledImage renderWith(const gpu::Context& ctx, MisMode mode) {
    RenderSettings s = testSettings(16, 16, 256, 1);  // direct light only
    s.mis = mode;
    s.seed = 71 + std::uint32_t(mode);
    return renderSamples(ctx, holedEmitterScene(), s);
}

TEST_F(GpuTest, LightSamplesInAlphaHolesOfAnEmitterBringNoLight) {
    const SampledImage bsdf = renderWith(*ctx, MisMode::BsdfOnly);
    ASSERT_GT(imageMean(bsdf.sums, bsdf.spp).mean, 0.02) << "the floor is lit";
    expectSameImage(bsdf, renderWith(*ctx, MisMode::LightOnly), "alpha-emitter-light-only", 8);
    expectSameImage(bsdf, renderWith(*ctx, MisMode::Both), "alpha-emitter-mis", 8);
}

}  // namespace
}  // namespace penumbra::test
