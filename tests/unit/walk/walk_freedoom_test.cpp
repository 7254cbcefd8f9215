// The walk map's grid on Freedoom's real levels (Debian package freedoom): its answers equal a
// brute-force scan of every line, and every map's player start is a place the player fits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>

#include "scene/io/wad/map.h"
#include "scene/io/wad/wad_file.h"
#include "scene/walk/wad_walk_map.h"
#include "scene/walk/walk_physics.h"
#include "../wad/freedoom_wad.h"

namespace penumbra::walk {
namespace {

std::vector<wad::MapData> allMaps(const std::string& bytes, const std::string& file) {
    wad::WadFile wad(bytes, file);
    std::vector<wad::MapData> maps;
    for (const wad::MapLumps& lumps : wad::findMaps(wad)) maps.push_back(wad::parseMap(wad, lumps));
    return maps;
}

// The rule of sectorAt, over every line.
std::int32_t sectorBruteForce(const WalkMap& map, double px, double py) {
    double best = INFINITY;
    std::int32_t sector = -1;
    for (const WalkLine& l : map.lines) {
        if ((l.y1 > py) == (l.y2 > py)) continue;
        const double xi = l.x1 + (py - l.y1) * (l.x2 - l.x1) / (l.y2 - l.y1);
        if (xi < px || xi >= best) continue;
        best = xi;
        sector = (l.x2 - l.x1) * (py - l.y1) - (l.y2 - l.y1) * (px - l.x1) < 0 ? l.front : l.back;
    }
    return sector;
}

// Whether the box crosses an impassable line, over every line.
bool blockedBruteForce(const WalkMap& map, double x, double y) {
    const double r = kPlayerRadius;
    for (const WalkLine& l : map.lines)
        if (l.impassable() && lineCrossesBox(l, x - r, y - r, x + r, y + r)) return true;
    return false;
}

TEST(WalkFreedoom, GridAnswersEqualBruteForceOnE1M1) {
    REQUIRE_WAD(bytes, "freedoom1.wad");
    const WalkMap map = buildWalkMap(allMaps(bytes, "freedoom1.wad").front());
    ASSERT_GT(map.lines.size(), 100u);
    double minX = INFINITY, maxX = -INFINITY, minY = INFINITY, maxY = -INFINITY;
    for (const WalkLine& l : map.lines) {
        minX = std::min({minX, l.x1, l.x2}), maxX = std::max({maxX, l.x1, l.x2});
        minY = std::min({minY, l.y1, l.y2}), maxY = std::max({maxY, l.y1, l.y2});
    }
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> ux(minX - 64, maxX + 64), uy(minY - 64, maxY + 64);
    int inside = 0;
    for (int i = 0; i < 4000; ++i) {
        // Half the points on integer coordinates, where vertices and lines lie.
        double x = ux(rng), y = uy(rng);
        if (i % 2) x = std::round(x), y = std::round(y);
        const std::int32_t s = sectorAt(map, x, y);
        ASSERT_EQ(s, sectorBruteForce(map, x, y)) << "at " << x << ", " << y;
        inside += s >= 0;
        if (s >= 0) {
            ASSERT_EQ(openingAt(map, x, y).blocked, blockedBruteForce(map, x, y)) << x << ", " << y;
        }
    }
    EXPECT_GT(inside, 400);  // the test looked inside the level, not only around it
}

void checkPlayerStarts(const std::string& bytes, const std::string& file) {
    for (const wad::MapData& data : allMaps(bytes, file)) {
        const WalkMap map = buildWalkMap(data);
        for (const wad::Thing& t : data.things) {
            if (t.type != 1) continue;
            std::optional<WalkState> s = placePlayer(map, t.x, t.y, -1e9);
            ASSERT_TRUE(s.has_value())
                << file << " " << data.name << ": the player start does not fit";
            // On the floor of the start's sector, and able to take a step somewhere.
            EXPECT_EQ(s->z, map.sectors[std::size_t(sectorAt(map, t.x, t.y))].floor) << data.name;
            int moved = 0;
            for (int d = 0; d < 8; ++d) {
                const double a = d * 0.785398;
                WalkState n =
                    stepWalk(map, *s, kWalkSpeed * std::cos(a), kWalkSpeed * std::sin(a), 0.05);
                moved += std::hypot(n.x - s->x, n.y - s->y) > 1;
            }
            EXPECT_GT(moved, 0) << file << " " << data.name << ": stuck at the start";
        }
    }
}

TEST(WalkFreedoom, EveryPlayerStartOfFreedoom1Fits) {
    REQUIRE_WAD(bytes, "freedoom1.wad");
    checkPlayerStarts(bytes, "freedoom1.wad");
}

TEST(WalkFreedoom, EveryPlayerStartOfFreedoom2Fits) {
    REQUIRE_WAD(bytes, "freedoom2.wad");
    checkPlayerStarts(bytes, "freedoom2.wad");
}

}  // namespace
}  // namespace penumbra::walk
