// Every specialised kernel renders what the generic one renders (issue 38 item 4): for scenes that
// between them set every capability the presets can, the kernels made for the scene (capabilities
// left out, promises made) and the generic kernels (every capability, no promise) give image means
// that agree within their noise, with independent seeds.
#include <cmath>
#include <string>

#include "gpu_fixture.h"
#include "render/kernel_features.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/presets.h"
#include "scoped_tuning.h"

namespace penumbra::test {
namespace {

RenderSettings tinyRender(std::uint32_t seed) {
    RenderSettings s;
    s.width = s.height = 32;
    s.samplesPerPixel = 64;
    s.samplesPerPass = 16;
    s.seed = seed;
    return s;
}

MeanEstimate renderMean(const gpu::Context& ctx, const Scene& scene, std::uint32_t seed, KernelSpec* spec) {
    Renderer renderer(ctx, scene, tinyRender(seed));
    renderer.render();
    *spec = renderer.kernelSpec();
    return imageMean(renderer.accumulation(), 64);
}

class KernelSpecTest : public GpuTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(KernelSpecTest, TheSceneKernelsRenderWhatTheGenericOnesDo) {
    const Scene scene = makePreset(GetParam());
    KernelSpec own, generic;
    const MeanEstimate a = renderMean(*ctx, scene, 7, &own);
    {
        ScopedTuning all;
        all.genericKernel(true);
        const MeanEstimate b = renderMean(*ctx, scene, 8, &generic);
        const double sigma = std::sqrt(a.stderr * a.stderr + b.stderr * b.stderr);
        EXPECT_NEAR(a.mean, b.mean, 5 * sigma) << kernelSpecNames(own) << " sigma " << sigma;
        EXPECT_LT(sigma, 0.1 * b.mean) << "the test has too little power to mean anything";  // the dungeon is dark: 5% there
    }
    EXPECT_EQ(generic, KernelSpec{});
    EXPECT_NE(own, generic) << "the scene's kernels were not specialised at all: the test compares nothing";
}

// Lambertian (Cornell), spheres and a sphere light (caffeine), glossy, glass and a sky (material
// spheres), textures, instances, a phantom and torches (dungeon), mirrors and glass around a mesh
// (bunny room).
INSTANTIATE_TEST_SUITE_P(Presets, KernelSpecTest,
                         ::testing::Values("cornell", "caffeine", "materials", "dungeon", "bunny-room"),
                         [](const auto& param) {
                             std::string name = param.param;
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });

}  // namespace
}  // namespace penumbra::test
