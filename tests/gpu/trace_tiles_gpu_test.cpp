// A pass split into tiles (render/passes/trace_tiles.h) renders exactly what one dispatch
// renders: every pixel keeps its index and its random numbers, so the sums agree bit for bit.
#include <cstring>

#include "gpu_fixture.h"
#include "render/passes/trace_tiles.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/presets.h"

namespace penumbra::test {
namespace {

using TraceTilesTest = GpuTest;

TEST_F(TraceTilesTest, TiledPassesRenderTheSameSumsAsOneDispatch) {
    const Scene scene = makeCornellBox();
    RenderSettings settings = testSettings(20, 12, 4, 4);  // 3 x 2 workgroups, the last ones partly outside
    settings.samplesPerPass = 2;
    Renderer whole(*ctx, scene, settings);
    settings.pathsPerDispatch = 2 * 64;  // one 8x8 workgroup at 2 samples per pass: six tiles
    Renderer tiled(*ctx, scene, settings);
    ASSERT_EQ(traceTiles(20, 12, 2, settings.pathsPerDispatch).size(), 6u);
    ASSERT_EQ(traceTiles(20, 12, 2, defaultPathBudget(ctx->info().type)).size(), 1u);
    whole.render();
    tiled.render();
    const std::vector<Vec4> a = whole.accumulation(), b = tiled.accumulation();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec4)), 0) << "tiling changed the image";
    EXPECT_EQ(whole.stats().closestRays, tiled.stats().closestRays);
    EXPECT_GT(tiled.stats().closestRays, 0u);
}

}  // namespace
}  // namespace penumbra::test
