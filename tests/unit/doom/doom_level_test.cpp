// A level that plays (scene/doom/level.h) on a small map built in memory (doom_test_map.h): a
// closed door blocks the player until it is used, a door closing on the player goes back up, a
// locked door wants its key, a switch moves its tagged sector and turns, a lift carries the
// player, and the exit switch ends the level. Walking is scene/walk's, on the level's heights.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "doom_test_map.h"
#include "scene/doom/level.h"
#include "scene/walk/walk_physics.h"

namespace penumbra::doom {
namespace {

constexpr double kTic = 1.0 / kTicsPerSecond;
constexpr double kEast = 0, kWest = std::numbers::pi;

PlayerPosition at(const walk::WalkState& s) { return {s.x, s.y, s.z}; }

// Walks with velocity (vx, vy) for `tics` tics, the level ticking along.
walk::WalkState walkFor(Level& level, walk::WalkState s, double vx, double vy, int tics) {
    for (int i = 0; i < tics; ++i) {
        const walk::WalkState before = s;
        s = walk::stepWalk(level.walkMap(), s, vx, vy, kTic);
        level.crossed(before.x, before.y, s.x, s.y);
        level.touchThings(at(s));
        level.tic(at(s));
    }
    return s;
}

walk::WalkState placed(const Level& level, double x, double y) {
    std::optional<walk::WalkState> s = walk::placePlayer(level.walkMap(), x, y, -1000);
    EXPECT_TRUE(s.has_value());
    return s.value_or(walk::WalkState{});
}

TEST(DoomLevel, PredictsTheRangesItsSectorsSweep) {
    const Level level(test::doomTestMap().map);
    const PlaneRange door = level.range(1, Plane::Ceiling);
    EXPECT_TRUE(door.moves);
    EXPECT_EQ(door.low, 0.0);
    EXPECT_EQ(door.high, 124.0);  // the lowest neighbouring ceiling less 4
    const PlaneRange lift = level.range(3, Plane::Floor);
    EXPECT_TRUE(lift.moves);
    EXPECT_EQ(lift.low, 0.0);
    EXPECT_EQ(lift.high, 64.0);
    EXPECT_FALSE(level.range(0, Plane::Floor).moves);
    EXPECT_FALSE(level.range(1, Plane::Floor).moves);
}

TEST(DoomLevel, ClosedDoorBlocksThenOpensAndLetsThePlayerThrough) {
    Level level(test::doomTestMap().map);
    walk::WalkState s = placed(level, 200, 128);
    s = walkFor(level, s, walk::kWalkSpeed, 0, 70);  // two seconds into the closed door
    EXPECT_LT(s.x, 256 - walk::kPlayerRadius + 0.01);
    EXPECT_TRUE(level.use(s.x, s.y, kEast, at(s)));
    s = walkFor(level, s, 0, 0, 62);  // 62 tics at 2 units: 124, open
    EXPECT_EQ(level.height(1, Plane::Ceiling), 124.0);
    s = walkFor(level, s, walk::kWalkSpeed, 0, 35);
    EXPECT_GT(s.x, 272 + walk::kPlayerRadius);  // through, into room B
}

TEST(DoomLevel, DoorClosingOnThePlayerGoesBackUp) {
    Level level(test::doomTestMap().map);
    walk::WalkState s = placed(level, 230, 128);
    ASSERT_TRUE(level.use(s.x, s.y, kEast, at(s)));
    s = walkFor(level, s, 0, 0, 63);
    s = walkFor(level, s, walk::kWalkSpeed, 0, 3);  // into the doorway, and stay there
    ASSERT_GT(s.x, 256 - walk::kPlayerRadius);
    ASSERT_LT(s.x, 272 + walk::kPlayerRadius);
    double lowest = 1e9;
    for (int t = 0; t < 400; ++t) {
        level.tic(at(s));
        lowest = std::min(lowest, level.height(1, Plane::Ceiling));
    }
    EXPECT_GE(lowest, s.z + walk::kPlayerHeight);  // never on the player's head
    EXPECT_LT(lowest, 124.0);                      // though it tried to close
}

TEST(DoomLevel, LockedDoorWantsItsKeyWhichIsPickedUpByWalkingOverIt) {
    const test::TestLevelMap map = test::doomTestMap();
    Level level(map.map);
    walk::WalkState s = placed(level, 300, 128);
    EXPECT_FALSE(level.use(s.x, s.y, kWest, at(s)));
    EXPECT_NE(level.takeMessage().find("blue key"), std::string::npos);
    EXPECT_FALSE(level.hasKey(Key::Blue));
    s = walkFor(level, s, 0, walk::kWalkSpeed, 9);       // north, toward the card at (400, 200)
    s = walkFor(level, s, walk::kWalkSpeed, 0, 12);
    EXPECT_TRUE(level.hasKey(Key::Blue)) << s.x << ", " << s.y;
    s = walkFor(level, s, -walk::kWalkSpeed, -walk::kWalkSpeed, 12);
    s = placed(level, 300, 128);
    EXPECT_TRUE(level.use(s.x, s.y, kWest, at(s)));
    EXPECT_EQ(level.activeMovers(), 1u);
}

TEST(DoomLevel, SwitchMovesItsTaggedSectorAndTurns) {
    const test::TestLevelMap map = test::doomTestMap();
    Level level(map.map);
    walk::WalkState s = placed(level, 40, 128);
    EXPECT_FALSE(level.switchFlipped(map.switchA));
    EXPECT_TRUE(level.use(s.x, s.y, kWest, at(s)));
    EXPECT_TRUE(level.switchFlipped(map.switchA));
    for (int t = 0; t < 10; ++t) level.tic(at(s));
    EXPECT_EQ(level.height(1, Plane::Ceiling), 20.0);  // the tagged door opens, 2 units a tic
    EXPECT_FALSE(level.use(s.x, s.y, kWest, at(s)));   // S1: spent
    for (int t = 0; t < 200; ++t) level.tic(at(s));
    EXPECT_EQ(level.height(1, Plane::Ceiling), 124.0);  // and stays open (door open, not raise)
    EXPECT_TRUE(level.switchFlipped(map.switchA));
}

TEST(DoomLevel, UseNeedsTheFrontAndReach) {
    const test::TestLevelMap map = test::doomTestMap();
    Level level(map.map);
    EXPECT_FALSE(level.use(40, 128, kEast));   // facing away from the switch
    EXPECT_FALSE(level.use(120, 128, kWest));  // 120 units away: out of reach
    EXPECT_EQ(level.activeMovers(), 0u);
}

TEST(DoomLevel, LiftCarriesThePlayerUpAndTheExitSwitchEndsTheLevel) {
    const test::TestLevelMap map = test::doomTestMap();
    Level level(map.map);
    walk::WalkState s = placed(level, 500, 128);
    ASSERT_TRUE(level.use(s.x, s.y, kEast, at(s)));
    EXPECT_TRUE(level.switchFlipped(map.liftSwitch));
    s = walkFor(level, s, 0, 0, 17);
    EXPECT_EQ(level.height(3, Plane::Floor), 0.0);
    EXPECT_TRUE(level.switchFlipped(map.liftSwitch));
    s = walkFor(level, s, walk::kWalkSpeed, 0, 12);  // onto the lowered lift
    EXPECT_TRUE(level.switchFlipped(map.liftSwitch));
    s = walkFor(level, s, 0, 0, 6);
    EXPECT_FALSE(level.switchFlipped(map.liftSwitch));  // SR: it turns back after 35 tics
    ASSERT_GT(s.x, 528 + walk::kPlayerRadius);
    EXPECT_EQ(s.z, 0.0);
    double previous = s.z;
    bool rose = false;
    for (int t = 0; t < 140; ++t) {
        s = walkFor(level, s, 0, 0, 1);
        EXPECT_GE(s.z, previous);
        rose |= s.z > previous;
        previous = s.z;
    }
    EXPECT_TRUE(rose);
    EXPECT_EQ(level.height(3, Plane::Floor), 64.0);
    EXPECT_EQ(s.z, 64.0);  // carried to the top
    EXPECT_FALSE(level.exited());
    s = walkFor(level, s, walk::kWalkSpeed, 0, 10);
    EXPECT_TRUE(level.use(s.x, s.y, kEast, at(s)));
    EXPECT_TRUE(level.exited());
    EXPECT_EQ(level.exitTic(), level.tics());
}

// Hostile maps: many special lines naming one tag shared by many sectors are read in time linear
// in their number (each tag and action is looked at once), and firing them all stays bounded.
TEST(DoomLevel, ManyLinesOnManyTaggedSectorsLoadQuickly) {
    wad::MapData map;
    map.name = "MAP01";
    map.vertices = {{0, 0}, {64, 0}};
    for (int s = 0; s < 20000; ++s) map.sectors.push_back({0, 128, "F", "C", 160, 0, 1});
    map.sidedefs.push_back({0, 0, "-", "-", "W", 0});
    for (int i = 0; i < 60000; ++i) map.linedefs.push_back({0, 1, 0, std::uint16_t(i % 2 ? 23 : 63), 1, 0, wad::kNoSide});
    const Level level(map);
    EXPECT_TRUE(level.range(19999, Plane::Floor).moves || level.range(19999, Plane::Ceiling).moves);
}

}  // namespace
}  // namespace penumbra::doom
