// Frame statistics (PN_OPTION_FRAME_STATS: primitives tested, closest hits, shadow rays blocked),
// as the viewer's panel and `bench --json` report them. Brute force tests every primitive for a
// closest hit and at most every one for a shadow ray, which bounds the count exactly; the
// megakernel and the wavefront draw the same random numbers, so they count the same; a closed box
// seen from inside (the furnace) is hit by every ray; the kernels without the feature count nothing.
#include "gpu_fixture.h"
#include "render/interactive_renderer.h"
#include "render/renderer.h"
#include "scene/presets/presets.h"
#include "scoped_tuning.h"

namespace penumbra::test {
namespace {

RenderSettings tiny(Accel accel) {
    RenderSettings s;
    s.width = 24;
    s.height = 20;
    s.samplesPerPixel = 1;
    s.samplesPerPass = 1;
    s.maxBounces = 3;
    s.accel = accel;
    return s;
}

RenderStats countedPass(gpu::Context& ctx, const Scene& scene, Accel accel) {
    Renderer r(ctx, scene, tiny(accel));
    r.setFrameStatistics(true);
    r.renderPasses(1, true);
    return r.stats();
}

TEST_F(GpuTest, BruteForceTestsEveryPrimitiveForEachClosestHitAndAtMostEveryOneForAShadowRay) {
    const Scene scene = makeCornellBox();
    const std::uint64_t n = scene.triangleCount();
    const RenderStats s = countedPass(*ctx, scene, Accel::Brute);
    ASSERT_GT(s.closestRays, 0u);
    ASSERT_GT(s.shadowRays, 0u);
    EXPECT_GT(s.shadowBlocked, 0u) << "the blocks shade the floor";
    EXPECT_LE(s.shadowBlocked, s.shadowRays);
    EXPECT_GT(s.closestHits, 0u);
    EXPECT_LT(s.closestHits, s.closestRays) << "the box's open front lets rays out";
    // An unblocked shadow ray tests them all; a blocked one stops at its occluder.
    EXPECT_GE(s.primitivesTested, (s.closestRays + s.shadowRays - s.shadowBlocked) * n);
    EXPECT_LE(s.primitivesTested, (s.closestRays + s.shadowRays) * n);
    EXPECT_LT(s.primitivesTested, (s.closestRays + s.shadowRays) * n) << "some blocked ray stopped early";

    // The BVH tests far fewer, for the same rays (same seed, same paths).
    const RenderStats bvh = countedPass(*ctx, scene, Accel::Bvh);
    EXPECT_EQ(bvh.closestRays, s.closestRays);
    EXPECT_EQ(bvh.shadowRays, s.shadowRays);
    EXPECT_EQ(bvh.shadowBlocked, s.shadowBlocked);
    EXPECT_EQ(bvh.closestHits, s.closestHits);
    EXPECT_LT(bvh.primitivesTested, s.primitivesTested);

    // Inside a closed box every ray hits something.
    const RenderStats closed = countedPass(*ctx, makePreset("furnace"), Accel::Bvh);
    EXPECT_GT(closed.closestRays, 0u);
    EXPECT_EQ(closed.closestHits, closed.closestRays);
}

TEST_F(GpuTest, MegakernelAndWavefrontCountTheSame) {
    const Scene scene = makePreset("caffeine");  // spheres and a plane, open to the sky: misses too
    RenderStats mega, wave;
    {
        ScopedTuning tuning;
        tuning.kernel("mega");
        mega = countedPass(*ctx, scene, Accel::Bvh);
    }
    {
        ScopedTuning tuning;
        tuning.kernel("wavefront");
        wave = countedPass(*ctx, scene, Accel::Bvh);
    }
    EXPECT_GT(mega.closestRays, mega.closestHits) << "some rays leave the scene";
    EXPECT_GT(mega.closestHits, 0u);
    EXPECT_EQ(mega.closestRays, wave.closestRays);
    EXPECT_EQ(mega.closestHits, wave.closestHits);
    EXPECT_EQ(mega.shadowRays, wave.shadowRays);
    EXPECT_EQ(mega.shadowBlocked, wave.shadowBlocked);
    EXPECT_EQ(mega.primitivesTested, wave.primitivesTested);
}

TEST_F(GpuTest, TheViewerCountsOnlyWhenAsked) {
    const Scene scene = makeCornellBox();
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(16, 12);
    auto frame = [&] {
        viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, ViewSettings{}); });
        viewer.finishFrame();
        return viewer.stats();
    };
    ViewerStats off = frame();
    EXPECT_FALSE(off.frameStatistics);
    EXPECT_GT(off.closestRays, 0u);
    EXPECT_EQ(off.primitivesTested + off.closestHits + off.shadowBlocked, 0u);
    viewer.setFrameStatistics(true);
    ViewerStats on = frame();
    EXPECT_TRUE(on.frameStatistics);
    EXPECT_GT(on.closestHits, 0u);
    EXPECT_LE(on.closestHits, on.closestRays);
    EXPECT_GT(on.primitivesTested, on.closestRays);
    EXPECT_GT(on.shadowBlocked, 0u);
    EXPECT_LE(on.shadowBlocked, on.shadowRays);
}

}  // namespace
}  // namespace penumbra::test
