// Transform invariance: a scene file that includes a world with a transform (rotate, uniform
// scale, translate; mirrors too) moves its geometry, lights and camera together, so the render must
// not change, within the statistical tolerance of the sample count. A mirrored world seen by the
// mirrored camera is the mirror image (the camera stays right-handed). The worlds have smooth
// shading normals (a wrong normal transform changes their shading), a one-sided emitting panel (a
// mirror must keep its front face) and every kind of light.
#include "../unit/image/test_dir.h"
#include "gpu_fixture.h"
#include "render_compare.h"
#include "scene/io/scene_json.h"
#include "test_worlds.h"

namespace penumbra::test {
namespace {

constexpr std::uint32_t kSize = 32;

struct WorldTransform {
    std::string keys;  // the scene file's transform keys
    bool mirrors;
};

// Renders `world` as it is, then included by a scene file with each transform, and expects the
// same image (mirrored left to right for a mirroring transform).
void expectInvariant(const gpu::Context& ctx, const Scene& world,
                     const std::vector<WorldTransform>& transforms, std::uint32_t spp,
                     const std::string& name) {
    TempDir dir;
    writeAll(dir / "world.json", sceneToJson(world));
    RenderSettings settings = testSettings(kSize, kSize, spp, 4);
    settings.seed = 1;
    const SampledImage reference = renderSamples(ctx, loadSceneJson(dir / "world.json"), settings);
    EXPECT_FALSE(compareBlocks(reference, mirroredLeftRight(reference), 4, 1e-4).agrees())
        << name << ": the comparison cannot tell the picture from its mirror image";
    for (std::size_t i = 0; i < transforms.size(); ++i) {
        SCOPED_TRACE(transforms[i].keys);
        writeAll(dir / "moved.json",
                 R"({"assets": [{"file": "world.json", )" + transforms[i].keys + "}]}");
        settings.seed = 2 + std::uint32_t(i);
        const SampledImage moved = renderSamples(ctx, loadSceneJson(dir / "moved.json"), settings);
        expectSameImage(reference, transforms[i].mirrors ? mirroredLeftRight(moved) : moved,
                        name + "-" + std::to_string(i));
    }
}

TEST_F(GpuTest, AreaLitWorldRendersTheSameRotatedScaledMovedAndMirrored) {
    expectInvariant(
        *ctx, areaLitWorld(),
        {{R"("scale": 2.5, "rotate": [30, 200, -15], "translate": [1.5, -1, 2.5])", false},
         {R"("scale": 0.4, "rotate": [-70, 45, 110], "translate": [-0.3, 0.5, 0.2])", false},
         {R"("scale": [-1.7, 1.7, 1.7], "rotate": [0, 60, 20], "translate": [1, 0, -1.5])", true},
         {R"("scale": [0.6, 0.6, -0.6], "rotate": [80, 0, 35])", true}},
        64, "area-lit-world");
}

TEST_F(GpuTest, PunctuallyLitWorldRendersTheSameRotatedMovedAndMirrored) {
    expectInvariant(
        *ctx, punctuallyLitWorld(),
        {{R"("rotate": [20, 130, -40], "translate": [1, 0.5, -1])", false},
         {R"("scale": [1, -1, 1], "rotate": [0, 30, 0], "translate": [0, 1, 0])", true}},
        64, "punctually-lit-world");
}

// Fifty metres from the origin a shadow ray's origin is pushed off its surface by about 1e-3 m
// (256 ulps, lib/offset.glsl). The ray used to stop 1e-4 of the distance short of the sampled
// emitter point, ran into the emitter itself and counted as shadowed (the floor under the panel
// lost 95% of its direct light); it now aims at the sample moved off the emitter's surface.
TEST_F(GpuTest, EmittersStillLightAWorldFiftyMetresFromTheOrigin) {
    expectInvariant(*ctx, areaLitWorld(), {{R"("translate": [0, 50, 0])", false}}, 64, "far-world");
}

}  // namespace
}  // namespace penumbra::test
