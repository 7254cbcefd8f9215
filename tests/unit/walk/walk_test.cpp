// Walking on small WAD maps written here: Doom's player rules (walls, steps, headroom, blocking
// lines, sliding, falling, no tunnelling), all in map units.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../wad/wad_builder.h"
#include "scene/io/wad/units.h"
#include "scene/io/wad/wad_loader.h"
#include "scene/walk/walk_physics.h"

namespace penumbra::walk {
namespace {
using testing::MapBuilder;
using testing::WadBuilder;

constexpr int kTwoSided = 0x0004, kBlocking = 0x0001, kBlockMonsters = 0x0002;

WalkMap walkMapOf(const MapBuilder& m) {
    WadBuilder wad;
    m.addTo(wad, "E1M1");
    testing::addTestGraphics(wad);
    Scene scene = loadWadFromMemory(wad.build("IWAD"), "", "walk.wad");
    EXPECT_TRUE(scene.walkMap.has_value());
    return scene.walkMap ? *scene.walkMap : WalkMap{};
}

// Room A (x 0..256, floor 0, ceiling 128) and room B (x 256..512, floorB..ceilingB), both
// y 0..height, joined by a two-sided line at x = 256 with the given flags.
WalkMap twoRooms(int floorB, int ceilingB, int middleFlags = kTwoSided, int height = 256) {
    MapBuilder m;
    const int a = m.sector(0, 128, "FLOOR1", "CEIL1", 160);
    const int b = m.sector(floorB, ceilingB, "FLOOR1", "CEIL1", 160);
    const int v00 = m.vertex(0, 0), v0h = m.vertex(0, height), vmh = m.vertex(256, height),
              vm0 = m.vertex(256, 0);
    const int vxh = m.vertex(512, height), vx0 = m.vertex(512, 0);
    auto wall = [&](int v1, int v2, int sector) {
        m.line(v1, v2, m.side(sector, "-", "-", "WALL1"));
    };
    wall(vm0, v00, a);
    wall(v00, v0h, a);
    wall(v0h, vmh, a);
    m.line(vmh, vm0, m.side(a, "WALL1", "WALL1", "-"), m.side(b, "WALL1", "WALL1", "-"),
           middleFlags);
    wall(vmh, vxh, b);
    wall(vxh, vx0, b);
    wall(vx0, vm0, b);
    m.thing(64, 128, 0, 1);
    return walkMapOf(m);
}

// Walks with a constant velocity for `seconds` in steps of dt.
WalkState walk(const WalkMap& map, WalkState s, double vx, double vy, double seconds,
               double dt = 1.0 / 60) {
    for (double t = 0; t < seconds - 1e-9; t += dt) s = stepWalk(map, s, vx, vy, dt);
    return s;
}

WalkState standAt(const WalkMap& map, double x, double y) {
    std::optional<WalkState> s = placePlayer(map, x, y, 0);
    EXPECT_TRUE(s.has_value()) << "cannot stand at " << x << ", " << y;
    return s.value_or(WalkState{});
}

TEST(Walk, AWallStopsThePlayerAtItsRadius) {
    const WalkMap map = twoRooms(0, 128);
    WalkState s = walk(map, standAt(map, 128, 128), -kWalkSpeed, 0, 2.0);
    EXPECT_NEAR(s.x, kPlayerRadius, 0.05);  // the west wall is at x = 0
    EXPECT_GE(s.x, kPlayerRadius);
    EXPECT_EQ(s.y, 128);
    EXPECT_EQ(s.z, 0);
}

TEST(Walk, ClimbsA24UnitStepButNotA25UnitOne) {
    const WalkMap low = twoRooms(24, 128), high = twoRooms(25, 128);
    WalkState up = walk(low, standAt(low, 128, 128), kWalkSpeed, 0, 2.0);
    EXPECT_NEAR(up.x, 512 - kPlayerRadius, 0.05) << "crossed room B to its east wall";
    EXPECT_EQ(up.z, 24);
    WalkState stopped = walk(high, standAt(high, 128, 128), kWalkSpeed, 0, 2.0);
    EXPECT_NEAR(stopped.x, 256 - kPlayerRadius, 0.05) << "stopped at the step";
    EXPECT_EQ(stopped.z, 0);
}

TEST(Walk, TooLowAnOpeningBlocks) {
    const WalkMap fits = twoRooms(0, 56), tooLow = twoRooms(0, 55), raisedFloor = twoRooms(16, 71);
    EXPECT_NEAR(walk(fits, standAt(fits, 128, 128), kWalkSpeed, 0, 2.0).x, 512 - kPlayerRadius,
                0.05);
    EXPECT_NEAR(walk(tooLow, standAt(tooLow, 128, 128), kWalkSpeed, 0, 2.0).x, 256 - kPlayerRadius,
                0.05);
    // A step the player could climb, under a ceiling 55 units above the raised floor.
    EXPECT_NEAR(walk(raisedFloor, standAt(raisedFloor, 128, 128), kWalkSpeed, 0, 2.0).x,
                256 - kPlayerRadius, 0.05);
}

TEST(Walk, BlockingLinesBlockAndMonsterBlockingLinesDoNot) {
    const WalkMap blocking = twoRooms(0, 128, kTwoSided | kBlocking);
    const WalkMap monsters = twoRooms(0, 128, kTwoSided | kBlockMonsters);
    EXPECT_NEAR(walk(blocking, standAt(blocking, 128, 128), kWalkSpeed, 0, 2.0).x,
                256 - kPlayerRadius, 0.05);
    EXPECT_NEAR(walk(monsters, standAt(monsters, 128, 128), kWalkSpeed, 0, 2.0).x,
                512 - kPlayerRadius, 0.05);
}

TEST(Walk, SlidesAlongAWallHitAtAnAngle) {
    const WalkMap map = twoRooms(0, 128, kTwoSided, 2048);
    const double v = kWalkSpeed / std::sqrt(2.0);  // 45 degrees towards the east wall
    WalkState s = walk(map, standAt(map, 400, 100), v, v, 2.0);
    EXPECT_NEAR(s.x, 512 - kPlayerRadius, 0.05);
    // Along the wall the velocity's component parallel to it carries on: 2 s at v, less the
    // bisection's few hundredths of a unit at the moment of contact.
    EXPECT_NEAR(s.y, 100 + 2.0 * v, 1.0);
}

TEST(Walk, FallsOffALedgeAndLandsOnTheLowerFloor) {
    MapBuilder m;
    // Room A is a 64-unit ledge above room B.
    const WalkMap map = [&] {
        const int a = m.sector(64, 192, "FLOOR1", "CEIL1", 160);
        const int b = m.sector(0, 192, "FLOOR1", "CEIL1", 160);
        const int v00 = m.vertex(0, 0), v0h = m.vertex(0, 256), vmh = m.vertex(256, 256),
                  vm0 = m.vertex(256, 0);
        const int vxh = m.vertex(512, 256), vx0 = m.vertex(512, 0);
        auto wall = [&](int v1, int v2, int sector) {
            m.line(v1, v2, m.side(sector, "-", "-", "WALL1"));
        };
        wall(vm0, v00, a), wall(v00, v0h, a), wall(v0h, vmh, a);
        m.line(vmh, vm0, m.side(a, "-", "-", "-"), m.side(b, "-", "WALL1", "-"), kTwoSided);
        wall(vmh, vxh, b), wall(vxh, vx0, b), wall(vx0, vm0, b);
        m.thing(64, 128, 0, 1);
        return walkMapOf(m);
    }();
    WalkState s = standAt(map, 200, 128);
    EXPECT_EQ(s.z, 64);
    bool airborne = false;
    for (int i = 0; i < 90; ++i) {  // 1.5 s at 146 units/s: off the ledge after 0.5 s
        s = stepWalk(map, s, kWalkSpeed / 2, 0, 1.0 / 60);
        airborne |= s.z > 0 && s.z < 64;
        EXPECT_LE(s.z, 64);
        EXPECT_GE(s.z, 0);
    }
    EXPECT_TRUE(airborne) << "the drop is a fall, not a jump";
    EXPECT_EQ(s.z, 0);
    EXPECT_EQ(s.vz, 0);
    EXPECT_GT(s.x, 256 + kPlayerRadius);
    // Doom's gravity: a fall of 64 units takes sqrt(2 * 64 / 1225) = 0.32 s.
    WalkState drop{300, 128, 64, 0};
    double t = 0;
    while (drop.z > 0 && t < 2) drop = stepWalk(map, drop, 0, 0, 1.0 / 140), t += 1.0 / 140;
    EXPECT_NEAR(t, std::sqrt(2 * 64 / kGravity), 0.02);
}

TEST(Walk, AFastMoveDoesNotPassAThinWall) {
    // Two rooms 4 units apart: the gap between them is solid.
    MapBuilder m;
    const int a = m.sector(0, 128, "FLOOR1", "CEIL1", 160);
    const int b = m.sector(0, 128, "FLOOR1", "CEIL1", 160);
    m.loop({{0, 0}, {0, 256}, {256, 256}, {256, 0}}, a, "WALL1");
    m.loop({{260, 0}, {260, 256}, {516, 256}, {516, 0}}, b, "WALL1");
    m.thing(64, 128, 0, 1);
    const WalkMap map = walkMapOf(m);
    // 1000 units in one step: far beyond the wall, the room behind it and the map.
    WalkState s = stepWalk(map, standAt(map, 128, 128), 10000, 0, 0.1);
    EXPECT_NEAR(s.x, 256 - kPlayerRadius, 0.05);
    // And a zero-thickness blocking line.
    const WalkMap line = twoRooms(0, 128, kTwoSided | kBlocking);
    EXPECT_NEAR(stepWalk(line, standAt(line, 128, 128), 10000, 0, 0.1).x, 256 - kPlayerRadius,
                0.05);
}

TEST(Walk, PlacementClampsToTheFloorAndRefusesWalls) {
    const WalkMap map = twoRooms(24, 100);
    EXPECT_EQ(placePlayer(map, 128, 128, -50)->z, 0);                    // below the floor: onto it
    EXPECT_EQ(placePlayer(map, 128, 128, 500)->z, 128 - kPlayerHeight);  // above: under the ceiling
    EXPECT_EQ(placePlayer(map, 300, 128, 60)->z, 100 - kPlayerHeight);
    EXPECT_EQ(placePlayer(map, 300, 128, 30)->z, 30);          // in between: where it was
    EXPECT_FALSE(placePlayer(map, 8, 128, 0).has_value());     // the box overlaps the west wall
    EXPECT_FALSE(placePlayer(map, -100, 128, 0).has_value());  // outside the map
}

TEST(Walk, NothingMovesOnBadInput) {
    const WalkMap map = twoRooms(0, 128);
    const WalkState s = standAt(map, 128, 128);
    for (double dt : {0.0, -1.0, double(NAN), double(INFINITY)}) {
        WalkState t = stepWalk(map, s, 100, 0, dt);
        EXPECT_EQ(t.x, s.x);
    }
    EXPECT_EQ(stepWalk(map, s, NAN, 0, 0.1).x, s.x);
}

TEST(Walk, MapUnitsRoundTripThroughTheScene) {
    const Vec3 p{123, -456, 41};
    const Vec3 scene = wad::mapToScene(p);
    EXPECT_NEAR(scene.x, 123 / 32.0, 1e-6);
    EXPECT_NEAR(scene.y, 41 / 32.0, 1e-6);
    EXPECT_NEAR(scene.z, 456 / 32.0, 1e-6);
    const Vec3 back = wad::sceneToMap(scene);
    EXPECT_NEAR(back.x, p.x, 1e-4);
    EXPECT_NEAR(back.y, p.y, 1e-4);
    EXPECT_NEAR(back.z, p.z, 1e-4);
}

}  // namespace
}  // namespace penumbra::walk
