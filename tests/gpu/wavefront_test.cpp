// The wavefront trace pass (render/passes/wavefront_pass.h) against the megakernel (trace.comp):
// every path draws the same random numbers in the same order and adds its vertices' light in the
// same order, so the two must give the same sums (bit for bit on lavapipe, to float rounding on a
// GPU: differingPixels) and trace the same rays. Scenes
// cover what the kernels specialise on: spheres, glass and absorption, textures, punctual lights,
// instances; and the pass's own paths: tiles, masked (adaptive) passes, more samples per pass, and
// the tail kernel taking over the last paths (never, part way, from the camera rays on).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "../unit/instanced_world.h"
#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/presets.h"
#include "scoped_tuning.h"
#include "test_worlds.h"

namespace penumbra::test {
namespace {

using WavefrontTest = GpuTest;

struct Traced {
    std::vector<Vec4> sums;
    RenderStats stats;
};

Traced renderWith(const gpu::Context& ctx, const std::string& kernel, const Scene& scene, const RenderSettings& settings,
                  const std::vector<std::uint32_t>* mask = nullptr, std::uint32_t tailPaths = 0) {
    ScopedTuning tuning;
    tuning.kernel(kernel).tailPaths(tailPaths);
    Renderer renderer(ctx, scene, settings);
    if (mask) {
        renderer.setActiveMask(*mask);
        renderer.renderPasses(2, true, true);
    } else {
        renderer.render();
    }
    return {renderer.accumulation(), renderer.stats()};
}

// Pixels whose sums differ. lavapipe compiles both kernels through the same LLVM passes, and they
// agree bit for bit. A GPU's compiler may fuse a multiply and an add in one kernel and not in the
// other (an H100 at a7ba3c3: up to 121 of 384 pixels differed in their last bits while every ray
// count agreed), so there a pixel differs when a sum is off by more than float rounding over a
// path's few dozen operations: a path that went another way differs by far more.
std::size_t differingPixels(const gpu::Context& ctx, const std::vector<Vec4>& a, const std::vector<Vec4>& b) {
    const bool bitExact = ctx.info().type == VK_PHYSICAL_DEVICE_TYPE_CPU;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (bitExact) {
            differing += std::memcmp(&a[i], &b[i], sizeof(Vec4)) != 0;
            continue;
        }
        const float pa[4] = {a[i].x, a[i].y, a[i].z, a[i].w}, pb[4] = {b[i].x, b[i].y, b[i].z, b[i].w};
        bool same = true;
        for (int c = 0; c < 4; ++c) same = same && std::fabs(pa[c] - pb[c]) <= 1e-4f * std::max(std::fabs(pa[c]), 1e-3f);
        differing += !same;
    }
    return differing;
}

void expectSameImage(const gpu::Context& ctx, const Scene& scene, const RenderSettings& settings,
                     const std::vector<std::uint32_t>* mask = nullptr) {
    const Traced mega = renderWith(ctx, "mega", scene, settings, mask);
    // The tail kernel never, once half a pass's paths are left, and for every path from the start.
    const std::uint64_t pathsPerPass = std::uint64_t(settings.width) * settings.height * settings.samplesPerPass;
    for (const std::uint32_t tailPaths : {0u, std::uint32_t(pathsPerPass / 2), UINT32_MAX}) {
        SCOPED_TRACE("waveTailPaths " + std::to_string(tailPaths));
        const Traced wave = renderWith(ctx, "wavefront", scene, settings, mask, tailPaths);
        ASSERT_EQ(mega.sums.size(), wave.sums.size());
        EXPECT_EQ(differingPixels(ctx, mega.sums, wave.sums), 0u) << "pixels whose sums differ between the kernels";
        if (!settings.shareCameraRays) {
            EXPECT_EQ(mega.stats.closestRays, wave.stats.closestRays);
        } else if (settings.pathsPerDispatch == 0 && !mask) {
            // Shared camera rays: the wavefront traces one per pixel (unless the tail starts
            // every path from its camera ray), the megakernel one per sample.
            const bool tailFromTheStart = tailPaths >= pathsPerPass;
            const std::uint64_t passes = settings.samplesPerPixel / settings.samplesPerPass;
            const std::uint64_t saved = tailFromTheStart ? 0
                                                         : std::uint64_t(settings.width) * settings.height *
                                                               (settings.samplesPerPass - 1) * passes;
            EXPECT_EQ(mega.stats.closestRays, wave.stats.closestRays + saved);
        } else {
            EXPECT_LE(wave.stats.closestRays, mega.stats.closestRays);  // tiles may go to the tail whole
        }
        EXPECT_EQ(mega.stats.shadowRays, wave.stats.shadowRays);
        EXPECT_EQ(wave.stats.invalidSamples, 0u);
        EXPECT_GT(wave.stats.shadowRays, 0u);
        double energy = 0;
        for (const Vec4& s : wave.sums) energy += s.x + s.y + s.z;
        EXPECT_GT(energy, 0.0) << "a black image would agree trivially";
    }
}

TEST_F(WavefrontTest, CornellBoxMatchesTheMegakernel) {
    expectSameImage(*ctx, makeCornellBox(), testSettings(20, 12, 4, 5));
}

TEST_F(WavefrontTest, GlassSpheresAndAbsorptionMatchTheMegakernel) {
    expectSameImage(*ctx, makeMaterialSpheres(), testSettings(24, 16, 2, 8));
}

TEST_F(WavefrontTest, TexturedPunctuallyLitAndInstancedScenesMatchTheMegakernel) {
    expectSameImage(*ctx, makeCaffeine(), testSettings(16, 16, 2, 4));
    expectSameImage(*ctx, punctuallyLitWorld(), testSettings(16, 12, 2, 4));
    expectSameImage(*ctx, instancedRoom(), testSettings(16, 12, 2, 4));
}

TEST_F(WavefrontTest, TilesSeveralSamplesPerPassAndMaskedPassesMatchTheMegakernel) {
    RenderSettings settings = testSettings(20, 12, 6, 4);
    settings.samplesPerPass = 3;
    settings.pathsPerDispatch = 3 * 64;  // one 8x8 workgroup a tile: six tiles, partial ones at the edges
    expectSameImage(*ctx, makeCornellBox(), settings);
    std::vector<std::uint32_t> mask(20 * 12, 0);
    for (std::size_t i = 0; i < mask.size(); i += 3) mask[i] = 1;
    expectSameImage(*ctx, makeCornellBox(), testSettings(20, 12, 2, 4), &mask);
}

// A pixel's samples in a pass sharing their camera ray: both kernels still agree (the
// wavefront tracing that ray once per pixel, over tiles too); at one sample per pass the bit
// changes nothing, and at more it changes the image (the samples' rays are no longer their own).
TEST_F(WavefrontTest, SharedCameraRaysMatchTheMegakernel) {
    RenderSettings settings = testSettings(20, 12, 8, 4);
    settings.samplesPerPass = 4;
    settings.shareCameraRays = true;
    expectSameImage(*ctx, makeCornellBox(), settings);
    settings.pathsPerDispatch = 4 * 64;
    expectSameImage(*ctx, makeCaffeine(), settings);

    RenderSettings one = testSettings(20, 12, 2, 4);
    one.samplesPerPass = 1;
    const Traced own = renderWith(*ctx, "wavefront", makeCornellBox(), one);
    one.shareCameraRays = true;
    const Traced shared = renderWith(*ctx, "wavefront", makeCornellBox(), one);
    ASSERT_EQ(own.sums.size(), shared.sums.size());
    EXPECT_EQ(std::memcmp(own.sums.data(), shared.sums.data(), own.sums.size() * sizeof(Vec4)), 0);

    settings = testSettings(20, 12, 8, 4);
    settings.samplesPerPass = 4;
    const Traced unshared = renderWith(*ctx, "wavefront", makeCornellBox(), settings);
    settings.shareCameraRays = true;
    const Traced four = renderWith(*ctx, "wavefront", makeCornellBox(), settings);
    EXPECT_NE(std::memcmp(unshared.sums.data(), four.sums.data(), unshared.sums.size() * sizeof(Vec4)), 0);
    EXPECT_LT(four.stats.closestRays, unshared.stats.closestRays);
}

}  // namespace
}  // namespace penumbra::test
