// Final renders whose instances move in place (Renderer::setInstanceTransforms, what a walk's
// video does when a Doom door moves): they render what a renderer made anew on the moved scene
// renders, for every walk that keeps records of the top level, and the denoiser's passes kept
// from the frame before denoise as new ones do. A scene whose movers all rest walks its rest tree
// (render/rest_tree.h) and renders what its two levels render.
#include <cstring>

#include "../unit/instanced_world.h"
#include "gpu_fixture.h"
#include "render/final_passes.h"
#include "render/progressive.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scoped_tuning.h"

namespace penumbra::test {
namespace {

// The instanced room and one more sphere placed by the identity (like a Doom door at rest: its
// instance walked untransformed), and the same room with that sphere and another one moved. Both
// stay inside the room, so the scene's bounds, and the light grid over them, are the same.
struct Move {
    Scene before, after;
};

Move sphereMove() {
    Move m;
    m.before = instancedRoom();
    m.before.instances.push_back({0, Affine{}});
    m.after = m.before;
    m.after.instances[1].transform = Affine::translation({-0.6f, 0.2f, 0.5f}) * m.after.instances[1].transform;
    m.after.instances.back().transform = Affine::translation({0.3f, 0.4f, 0.0f});
    return m;
}

RenderSettings moveSettings(Accel accel) {
    RenderSettings s = testSettings(24, 24, 16, 4);
    s.accel = accel;
    s.seed = 5;
    return s;
}

// Bit for bit on lavapipe (the same arrays, seed and kernels); GPUs may round the two apart.
void expectSameSums(const gpu::Context& ctx, const std::vector<Vec4>& a, const std::vector<Vec4>& b, const char* what) {
    ASSERT_EQ(a.size(), b.size());
    if (ctx.info().type == VK_PHYSICAL_DEVICE_TYPE_CPU) {
        EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec4)), 0) << what << ": in place and anew differ";
    } else {
        const double mean = imageMean(b, 16).mean;
        EXPECT_NEAR(imageMean(a, 16).mean, mean, 1e-4 * mean) << what;
    }
}

TEST_F(GpuTest, InstancesMovedInPlaceRenderAsANewRenderer) {
    const Move m = sphereMove();
    // Wide keeps the binary walk in two-level scenes; the stackless escapes and the objects' boxes
    // are records of the top level the move rebuilds.
    for (Accel accel : {Accel::Bvh, Accel::Stackless, Accel::Objects}) {
        Renderer updated(*ctx, m.before, moveSettings(accel));
        updated.render();
        const std::vector<Vec4> old = updated.accumulation();
        updated.setInstanceTransforms(m.after);
        updated.restart(m.after.camera);
        updated.render();
        Renderer fresh(*ctx, m.after, moveSettings(accel));
        fresh.render();
        const std::vector<Vec4> a = updated.accumulation();
        EXPECT_NE(std::memcmp(a.data(), old.data(), a.size() * sizeof(Vec4)), 0) << accelName(accel) << ": nothing moved";
        expectSameSums(*ctx, a, fresh.accumulation(), accelName(accel));
    }
}

std::vector<Vec4> renderSums(const gpu::Context& ctx, const Scene& scene, Accel accel, bool restTree) {
    ScopedTuning tuning;
    tuning.restTree(restTree);
    Renderer r(ctx, scene, moveSettings(accel));
    EXPECT_EQ(r.sceneArrays().restRoot != PN_NO_HIT, restTree);
    r.render();
    return r.accumulation();
}

TEST_F(GpuTest, MoversAtRestRenderThroughTheRestTreeAsThroughTwoLevels) {
    const Scene scene = moversAtRest();
    for (Accel accel : {Accel::Bvh, Accel::Stackless})
        expectSameSums(*ctx, renderSums(*ctx, scene, accel, true), renderSums(*ctx, scene, accel, false),
                       accelName(accel));
}

// A door raised walks two levels, and back at rest the rest tree again: each frame as a renderer
// made anew on the scene as it then stands.
TEST_F(GpuTest, ADoorRaisedAndLoweredInPlaceRendersAsNewRenderers) {
    const Scene rest = moversAtRest();
    Scene raised = rest;
    raised.instances[0].transform = doorRaised(1.2f);
    for (Accel accel : {Accel::Bvh, Accel::Stackless}) {
        Renderer updated(*ctx, rest, moveSettings(accel));
        updated.render();
        updated.setInstanceTransforms(raised);
        updated.restart(raised.camera);
        updated.render();
        expectSameSums(*ctx, updated.accumulation(), renderSums(*ctx, raised, accel, false), accelName(accel));
        updated.setInstanceTransforms(rest);
        updated.restart(rest.camera);
        updated.render();
        expectSameSums(*ctx, updated.accumulation(), renderSums(*ctx, rest, accel, true), accelName(accel));
    }
}

TEST_F(GpuTest, DenoisingPassesKeptAcrossAMoveDenoiseAsNewOnes) {
    const Move m = sphereMove();
    Renderer updated(*ctx, m.before, moveSettings(Accel::Bvh));
    FinalFramePasses kept(*ctx, updated);
    {
        ProgressiveRender first(updated, AdaptiveSettings{});
        first.run(samplesBudget(16));
        kept.denoise(first.current());
    }
    updated.setInstanceTransforms(m.after);
    updated.restart(m.after.camera);
    kept.restart();
    ProgressiveRender second(updated, AdaptiveSettings{});
    second.run(samplesBudget(16));
    const ImageRgb a = kept.denoise(second.current());

    Renderer fresh(*ctx, m.after, moveSettings(Accel::Bvh));
    ProgressiveRender render(fresh, AdaptiveSettings{});
    render.run(samplesBudget(16));
    const ImageRgb b = FinalFramePasses(*ctx, fresh).denoise(render.current());
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    double sumA = 0, sumB = 0;
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        sumA += luminance(a.pixels[i]);
        sumB += luminance(b.pixels[i]);
        for (int c = 0; c < 3; ++c) differ += a.pixels[i][c] != b.pixels[i][c];
    }
    if (ctx->info().type == VK_PHYSICAL_DEVICE_TYPE_CPU) EXPECT_EQ(differ, 0u) << "kept and new passes differ";
    else EXPECT_NEAR(sumA, sumB, 1e-4 * sumB);
}

}  // namespace
}  // namespace penumbra::test
