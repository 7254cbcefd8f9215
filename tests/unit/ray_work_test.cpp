// The ray bench's work per ray from raybench_count.comp's words: means over the rays traced, and
// the share of warp lanes busy while each warp's longest walk runs.
#include <gtest/gtest.h>

#include <vector>

#include "render/ray_bench.h"
#include "shared/types.h"

namespace penumbra {
namespace {

std::uint32_t word(std::uint32_t nodes, std::uint32_t primitives) { return nodes | (primitives << PN_RAY_WORK_BITS); }

TEST(RayWork, MeansCountOnlyTracedRays) {
    std::vector<std::uint32_t> words(PN_TRACE_GROUP_X * 8, 0u);  // one group wide, 8 rows: two warps
    words[0] = word(10, 2);
    words[1] = word(20, 4);
    const TraversalWork w = traversalWork(words, PN_TRACE_GROUP_X, 8);
    EXPECT_EQ(w.rays, 2u);
    EXPECT_DOUBLE_EQ(w.nodesPerRay, 15.0);
    EXPECT_DOUBLE_EQ(w.primitivesPerRay, 3.0);
    // One warp ran 20 steps on 32 lanes; the other traced nothing and costs nothing.
    EXPECT_DOUBLE_EQ(w.laneUse, 30.0 / (20.0 * 32.0));
}

TEST(RayWork, EqualWalksKeepEveryLaneBusy) {
    const std::uint32_t width = 3 * PN_TRACE_GROUP_X, height = 8;
    std::vector<std::uint32_t> words(width * height, word(7, 1));
    const TraversalWork w = traversalWork(words, width, height);
    EXPECT_EQ(w.rays, std::uint64_t(width) * height);
    EXPECT_DOUBLE_EQ(w.laneUse, 1.0);
}

TEST(RayWork, LanesOutsideTheImageAreIdleLanes) {
    // 4 pixels wide: each warp keeps 32 lanes for 16 pixels of rays.
    std::vector<std::uint32_t> words(4 * 8, word(5, 0));
    EXPECT_DOUBLE_EQ(traversalWork(words, 4, 8).laneUse, 0.5);
}

TEST(RayWork, NoRaysGiveZeros) {
    std::vector<std::uint32_t> words(16, 0u);
    const TraversalWork w = traversalWork(words, 4, 4);
    EXPECT_EQ(w.rays, 0u);
    EXPECT_EQ(w.laneUse, 0.0);
}

}  // namespace
}  // namespace penumbra
