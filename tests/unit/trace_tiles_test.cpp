// The trace pass's tiles (render/passes/trace_tiles.h): they cover every pixel exactly once,
// stay within the path budget (down to one workgroup), and start on workgroup boundaries.
#include <gtest/gtest.h>

#include <vector>

#include "render/passes/trace_tiles.h"
#include "shared/types.h"

namespace penumbra {
namespace {

struct Case {
    std::uint32_t width, height, spp;
    std::uint64_t budget;
};

TEST(TraceTiles, CoverEveryPixelOnceWithinTheBudget) {
    const Case cases[] = {{1, 1, 1, 1},          {8, 8, 1, 64},          {17, 9, 1, 64},      {640, 480, 1, 1u << 14},
                          {1920, 1080, 4, 1u << 22}, {16384, 3, 64, 1u << 14}, {100, 100, 1, 1u << 30},
                          {33, 70, 16, 1000},    {512, 512, 1, 1}};
    for (const Case& c : cases) {
        const std::vector<TraceTile> tiles = traceTiles(c.width, c.height, c.spp, c.budget);
        std::vector<int> covered(std::size_t(c.width) * c.height, 0);
        for (const TraceTile& t : tiles) {
            ASSERT_LE(t.x + t.width, c.width);
            ASSERT_LE(t.y + t.height, c.height);
            EXPECT_EQ(t.x % PN_TRACE_GROUP_X, 0u);
            EXPECT_EQ(t.y % PN_TRACE_GROUP_Y, 0u);
            const std::uint64_t paths = std::uint64_t(t.width) * t.height * c.spp;
            const std::uint64_t oneGroup = std::uint64_t(PN_TRACE_GROUP_X) * PN_TRACE_GROUP_Y * c.spp;
            EXPECT_LE(paths, std::max(c.budget, oneGroup)) << c.width << "x" << c.height << " tile at " << t.x << "," << t.y;
            for (std::uint32_t y = t.y; y < t.y + t.height; ++y)
                for (std::uint32_t x = t.x; x < t.x + t.width; ++x) ++covered[std::size_t(y) * c.width + x];
        }
        for (std::size_t i = 0; i < covered.size(); ++i) ASSERT_EQ(covered[i], 1) << c.width << "x" << c.height << " pixel " << i;
    }
}

TEST(TraceTiles, AGenerousBudgetIsOneDispatch) {
    const std::vector<TraceTile> tiles = traceTiles(1920, 1080, 1, 1u << 22);
    ASSERT_EQ(tiles.size(), 1u);
    EXPECT_EQ(tiles[0].width, 1920u);
    EXPECT_EQ(tiles[0].height, 1080u);
}

TEST(TraceTiles, ACpuDeviceGetsASmallerBudgetThanAGpu) {
    EXPECT_LT(defaultPathBudget(VK_PHYSICAL_DEVICE_TYPE_CPU), defaultPathBudget(VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU));
    EXPECT_EQ(defaultPathBudget(VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU), defaultPathBudget(VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU));
}

}  // namespace
}  // namespace penumbra
