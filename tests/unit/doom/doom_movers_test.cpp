// Doom's sector movers against the game's own timings (p_doors.c, p_plats.c, p_ceilng.c): a door
// rises at 2 units a tic, waits 150 tics and closes; a fast door moves 4x; a lift drops at 4
// units a tic, waits 105 tics and comes back; a door closing on the player goes back up.
#include <gtest/gtest.h>

#include <vector>

#include "scene/doom/sector_movers.h"

namespace penumbra::doom {
namespace {

// Sectors as plain heights; `minGap`: a thing standing in every sector needs that much room.
struct FakeWorld final : PlaneWorld {
    std::vector<double> floors, ceilings;
    double minGap = 0;
    double height(int s, Plane p) const override { return p == Plane::Floor ? floors[s] : ceilings[s]; }
    void setHeight(int s, Plane p, double h) override { (p == Plane::Floor ? floors[s] : ceilings[s]) = h; }
    bool thingsFit(int s) const override { return ceilings[s] - floors[s] >= minGap; }
};

// Runs a mover until it finishes, recording the plane's height after each tic.
template <class M, class Tic>
std::vector<double> run(M& mover, FakeWorld& world, Plane plane, Tic tic, int limit = 10000) {
    std::vector<double> heights;
    while (int(heights.size()) < limit) {
        const bool going = tic(mover, world);
        heights.push_back(world.height(mover.sector, plane));
        if (!going) break;
    }
    return heights;
}

TEST(DoomMovers, DoorOpensWaitsAndClosesOnDoomsTimings) {
    FakeWorld w;
    w.floors = {0};
    w.ceilings = {0};
    Door d;
    d.kind = DoorKind::Normal;
    d.topHeight = 128;
    const std::vector<double> h = run(d, w, Plane::Ceiling, ticDoor);
    // 64 tics up at 2 units; as in T_MovePlane, the tic after a step lands exactly on the top is
    // the one that finds it there; then 150 tics open, 64 tics down and the tic that finds the floor.
    ASSERT_EQ(h.size(), 64u + 1u + 150u + 64u + 1u);
    for (int t = 0; t < 64; ++t) EXPECT_EQ(h[std::size_t(t)], 2.0 * (t + 1)) << "tic " << t;
    for (int t = 64; t < 64 + 1 + 150; ++t) EXPECT_EQ(h[std::size_t(t)], 128.0) << "tic " << t;
    for (int t = 0; t < 64; ++t) EXPECT_EQ(h[std::size_t(215 + t)], 128.0 - 2.0 * (t + 1));
    EXPECT_EQ(h.back(), 0.0);
}

TEST(DoomMovers, FastDoorMovesFourTimesAsFast) {
    FakeWorld w;
    w.floors = {0};
    w.ceilings = {0};
    Door d;
    d.kind = DoorKind::BlazeOpen;
    d.speed = kDoorSpeed * 4;
    d.topHeight = 124;  // not a multiple of 8: the last step stops at the top
    const std::vector<double> h = run(d, w, Plane::Ceiling, ticDoor);
    ASSERT_EQ(h.size(), 16u);  // ceil(124 / 8); an open door stays open
    EXPECT_EQ(h[14], 120.0);
    EXPECT_EQ(h.back(), 124.0);
}

TEST(DoomMovers, ClosingDoorGoesBackUpWhenThePlayerIsUnderIt) {
    FakeWorld w;
    w.floors = {0};
    w.ceilings = {72};
    w.minGap = 56;  // the player stands in the doorway
    Door d;
    d.kind = DoorKind::Normal;
    d.topHeight = 72;
    d.direction = -1;
    EXPECT_TRUE(ticDoor(d, w));  // 70: still fits
    EXPECT_EQ(w.ceilings[0], 70.0);
    for (int i = 0; i < 7; ++i) ticDoor(d, w);  // down to 56
    EXPECT_EQ(w.ceilings[0], 56.0);
    EXPECT_EQ(d.direction, -1);
    ticDoor(d, w);  // 54 would crush: undone, and the door reverses
    EXPECT_EQ(w.ceilings[0], 56.0);
    EXPECT_EQ(d.direction, 1);
    ticDoor(d, w);
    EXPECT_EQ(w.ceilings[0], 58.0);
}

TEST(DoomMovers, CloseDoorDoesNotReverse) {
    FakeWorld w;
    w.floors = {0};
    w.ceilings = {60};
    w.minGap = 56;
    Door d;
    d.kind = DoorKind::Close;
    d.direction = -1;
    for (int i = 0; i < 10; ++i) ticDoor(d, w);
    EXPECT_EQ(w.ceilings[0], 56.0);  // it waits on the player's head
    EXPECT_EQ(d.direction, -1);
}

TEST(DoomMovers, LiftLowersWaitsAndReturns) {
    FakeWorld w;
    w.floors = {64};
    w.ceilings = {192};
    Plat p;
    p.kind = PlatKind::DownWaitUpStay;
    p.low = 0;
    p.high = 64;
    const std::vector<double> h = run(p, w, Plane::Floor, ticPlat);
    // 16 tics down at 4 units and the tic that finds the bottom, 105 tics waiting (the last one
    // turns it), 16 tics up and the tic that finds the top, where it stays.
    ASSERT_EQ(h.size(), 16u + 1u + 105u + 16u + 1u);
    for (int t = 0; t < 16; ++t) EXPECT_EQ(h[std::size_t(t)], 64.0 - 4.0 * (t + 1));
    for (int t = 16; t < 16 + 1 + 105; ++t) EXPECT_EQ(h[std::size_t(t)], 0.0) << "tic " << t;
    for (int t = 0; t < 16; ++t) EXPECT_EQ(h[std::size_t(122 + t)], 4.0 * (t + 1));
    EXPECT_EQ(h.back(), 64.0);
}

TEST(DoomMovers, RisingLiftGoesBackDownWhenBlocked) {
    FakeWorld w;
    w.floors = {0};
    w.ceilings = {60};
    w.minGap = 56;
    Plat p;
    p.kind = PlatKind::DownWaitUpStay;
    p.low = 0;
    p.high = 8;
    p.status = PlatStatus::Up;
    ticPlat(p, w);  // 4: fits
    EXPECT_EQ(w.floors[0], 4.0);
    ticPlat(p, w);  // 8 would leave 52: undone, down again
    EXPECT_EQ(w.floors[0], 4.0);
    EXPECT_EQ(p.status, PlatStatus::Down);
}

TEST(DoomMovers, CrusherGoesDownToEightAboveTheFloorAndBackUp) {
    FakeWorld w;
    w.floors = {0};
    w.ceilings = {72};
    CeilingMove c;
    c.kind = CeilingKind::CrushAndRaise;
    c.bottomHeight = 8;
    c.topHeight = 72;
    c.crush = true;
    for (int i = 0; i < 64; ++i) ticCeiling(c, w);
    EXPECT_EQ(w.ceilings[0], 8.0);
    EXPECT_EQ(c.direction, -1);
    ticCeiling(c, w);  // finds the bottom
    EXPECT_EQ(c.direction, 1);
    for (int i = 0; i < 65; ++i) ticCeiling(c, w);
    EXPECT_EQ(w.ceilings[0], 72.0);
    EXPECT_EQ(c.direction, -1);  // and again, forever
}

TEST(DoomMovers, CrusherSlowsToAnEighthWhileItCrushes) {
    FakeWorld w;
    w.floors = {0};
    w.ceilings = {58};
    w.minGap = 56;
    CeilingMove c;
    c.kind = CeilingKind::CrushAndRaise;
    c.bottomHeight = 8;
    c.topHeight = 58;
    c.crush = true;
    ticCeiling(c, w);  // 57
    ticCeiling(c, w);  // 56
    ticCeiling(c, w);  // 55: crushing, it keeps going but slows down
    EXPECT_EQ(w.ceilings[0], 55.0);
    EXPECT_EQ(c.speed, kCeilingSpeed / 8);
    ticCeiling(c, w);
    EXPECT_EQ(w.ceilings[0], 55.0 - 1.0 / 8);
}

}  // namespace
}  // namespace penumbra::doom
