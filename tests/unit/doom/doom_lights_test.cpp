// Doom's sector light specials follow the game's periods (p_lights.c): a synchronised fast strobe
// is dark 15 tics and bright 5 (period 20), a slow one dark 35 and bright 5 (40), a glow falls
// and rises 8 levels a tic between its neighbours' dimmest light and its own.
#include <gtest/gtest.h>

#include <vector>

#include "doom_test_map.h"
#include "scene/doom/level.h"

namespace penumbra::doom {
namespace {

// The light of sector 0 (room A, level 160 beside the door's 160) with `special`: as loaded, then
// after each of `tics` tics.
std::vector<int> lightOver(int special, int tics, int doorLight = 160) {
    wad::MapData map = test::doomTestMap().map;
    map.sectors[0].special = std::uint16_t(special);
    map.sectors[1].lightLevel = std::int16_t(doorLight);
    Level level(map);
    std::vector<int> out{level.lightLevel(0)};
    for (int t = 0; t < tics; ++t) {
        level.tic(std::nullopt);
        out.push_back(level.lightLevel(0));
    }
    return out;
}

// The lengths of the runs of equal levels after the first change.
std::vector<int> runs(const std::vector<int>& light) {
    std::vector<int> out;
    int length = 0;
    for (std::size_t t = 1; t < light.size(); ++t) {
        ++length;
        if (light[t] != light[t - 1]) {
            out.push_back(length);
            length = 0;
        }
    }
    if (!out.empty()) out.erase(out.begin());  // the run before the first change
    return out;
}

TEST(DoomLights, SynchronisedFastStrobeIsDarkFifteenTicsAndBrightFive) {
    const std::vector<int> light = lightOver(13, 200);
    EXPECT_EQ(light[0], 160);
    EXPECT_EQ(light[1], 0);  // in sync: it goes dark on the first tic (no dimmer neighbour: 0)
    for (int l : light) EXPECT_TRUE(l == 0 || l == 160) << l;  // nothing dimmer around: dark is 0
    const std::vector<int> r = runs(light);
    ASSERT_GE(r.size(), 8u);
    for (std::size_t i = 0; i < r.size(); ++i) EXPECT_EQ(r[i], i % 2 == 0 ? 15 : 5) << "run " << i;
    for (std::size_t t = 20; t < light.size(); ++t) EXPECT_EQ(light[t], light[t - 20]);  // period 20
}

TEST(DoomLights, SynchronisedSlowStrobeHasPeriodForty) {
    const std::vector<int> light = lightOver(12, 300, 96);
    for (int l : light) EXPECT_TRUE(l == 96 || l == 160) << l;  // down to the door's 96
    const std::vector<int> r = runs(light);
    ASSERT_GE(r.size(), 8u);
    for (std::size_t i = 0; i < r.size(); ++i) EXPECT_EQ(r[i], i % 2 == 0 ? 35 : 5) << "run " << i;
    for (std::size_t t = 40; t < light.size(); ++t) EXPECT_EQ(light[t], light[t - 40]);
}

TEST(DoomLights, GlowFallsAndRisesEightLevelsATic) {
    const std::vector<int> light = lightOver(8, 200, 64);
    // From 160 down to above 64 and back up below 160, 8 a tic: (160 - 72) / 8 = 11 steps each way.
    for (std::size_t t = 1; t < light.size(); ++t) {
        EXPECT_LE(std::abs(light[t] - light[t - 1]), 8);
        EXPECT_GT(light[t], 64);
        EXPECT_LT(light[t], 160);
    }
    const int period = 2 * (160 - 72) / 8;
    for (std::size_t t = std::size_t(period) + 1; t < light.size(); ++t) EXPECT_EQ(light[t], light[t - period]) << t;
}

TEST(DoomLights, RandomLightsRepeatRunToRun) {
    for (int special : {1, 2, 3, 17}) {
        const std::vector<int> a = lightOver(special, 300, 64), b = lightOver(special, 300, 64);
        EXPECT_EQ(a, b) << "special " << special;
        EXPECT_GT(runs(a).size(), 3u) << "special " << special << " changes";
    }
}

}  // namespace
}  // namespace penumbra::doom
