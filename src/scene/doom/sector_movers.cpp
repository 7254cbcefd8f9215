#include "scene/doom/sector_movers.h"

#include <type_traits>

namespace penumbra::doom {
namespace {

// Sets a plane and undoes it when something no longer fits; true when it had to be undone.
bool moveAndCheck(PlaneWorld& world, int sector, Plane plane, double to, bool keepIfSqueezed) {
    const double from = world.height(sector, plane);
    world.setHeight(sector, plane, to);
    if (world.thingsFit(sector)) return false;
    if (!keepIfSqueezed) world.setHeight(sector, plane, from);
    return true;
}

}  // namespace

MoveResult movePlane(PlaneWorld& world, int sector, Plane plane, double speed, double dest, bool crush,
                     int direction) {
    const double now = world.height(sector, plane);
    // Moving toward the other plane may squeeze things: floors going up, ceilings going down.
    const bool closing = (plane == Plane::Floor) == (direction > 0);
    const bool overshoots = direction > 0 ? now + speed > dest : now - speed < dest;
    if (overshoots) {
        // The last step lands on dest; if that squeezes something, the plane stays (and the
        // mover is told it arrived all the same, as T_MovePlane does).
        if (closing) moveAndCheck(world, sector, plane, dest, false);
        else world.setHeight(sector, plane, dest);
        return MoveResult::PastDest;
    }
    const double next = now + (direction > 0 ? speed : -speed);
    if (!closing) {
        world.setHeight(sector, plane, next);
        return MoveResult::Moved;
    }
    return moveAndCheck(world, sector, plane, next, crush) ? MoveResult::Crushed : MoveResult::Moved;
}

bool ticDoor(Door& d, PlaneWorld& world) {
    if (d.direction == 0) {  // waiting
        if (--d.countdown > 0) return true;
        if (d.kind == DoorKind::Normal || d.kind == DoorKind::BlazeRaise) d.direction = -1;
        else if (d.kind == DoorKind::Close30ThenOpen) d.direction = 1;
        return true;
    }
    if (d.direction < 0) {
        const double floor = world.height(d.sector, Plane::Floor);
        const MoveResult r = movePlane(world, d.sector, Plane::Ceiling, d.speed, floor, false, -1);
        if (r == MoveResult::PastDest) {
            if (d.kind != DoorKind::Close30ThenOpen) return false;
            d.direction = 0;
            d.countdown = kClose30Wait;
        } else if (r == MoveResult::Crushed && d.kind != DoorKind::Close && d.kind != DoorKind::BlazeClose) {
            d.direction = 1;  // something is in the way: back up
        }
        return true;
    }
    const MoveResult r = movePlane(world, d.sector, Plane::Ceiling, d.speed, d.topHeight, false, 1);
    if (r != MoveResult::PastDest) return true;
    if (d.kind == DoorKind::Normal || d.kind == DoorKind::BlazeRaise) {
        d.direction = 0;
        d.countdown = d.topWait;
        return true;
    }
    return false;  // Open, BlazeOpen, Close30ThenOpen: done once open
}

bool ticPlat(Plat& p, PlaneWorld& world) {
    if (p.inStasis) return true;
    switch (p.status) {
        case PlatStatus::Up: {
            const MoveResult r = movePlane(world, p.sector, Plane::Floor, p.speed, p.high, p.crush, 1);
            if (r == MoveResult::Crushed && !p.crush) {
                p.count = p.wait;
                p.status = PlatStatus::Down;
            } else if (r == MoveResult::PastDest) {
                p.count = p.wait;
                p.status = PlatStatus::Waiting;
                if (p.kind != PlatKind::PerpetualRaise) return false;
            }
            return true;
        }
        case PlatStatus::Down:
            if (movePlane(world, p.sector, Plane::Floor, p.speed, p.low, false, -1) == MoveResult::PastDest) {
                p.count = p.wait;
                p.status = PlatStatus::Waiting;
            }
            return true;
        case PlatStatus::Waiting:
            if (--p.count <= 0)
                p.status = world.height(p.sector, Plane::Floor) == p.low ? PlatStatus::Up : PlatStatus::Down;
            return true;
    }
    return true;
}

bool ticFloor(FloorMove& f, PlaneWorld& world) {
    return movePlane(world, f.sector, Plane::Floor, f.speed, f.dest, f.crush, f.direction) != MoveResult::PastDest;
}

bool ticCeiling(CeilingMove& c, PlaneWorld& world) {
    if (c.inStasis) return true;
    const bool crusher = c.kind == CeilingKind::CrushAndRaise || c.kind == CeilingKind::FastCrushAndRaise ||
                         c.kind == CeilingKind::SilentCrushAndRaise;
    if (c.direction > 0) {
        const MoveResult r = movePlane(world, c.sector, Plane::Ceiling, c.speed, c.topHeight, false, 1);
        if (r != MoveResult::PastDest) return true;
        if (!crusher) return false;
        c.direction = -1;
        return true;
    }
    const MoveResult r = movePlane(world, c.sector, Plane::Ceiling, c.speed, c.bottomHeight, c.crush, -1);
    if (r == MoveResult::PastDest) {
        if (!crusher) return false;
        if (c.kind != CeilingKind::FastCrushAndRaise) c.speed = kCeilingSpeed;
        c.direction = 1;
    } else if (r == MoveResult::Crushed && c.kind != CeilingKind::FastCrushAndRaise &&
               c.kind != CeilingKind::LowerToFloor && c.kind != CeilingKind::RaiseToHighest) {
        c.speed = kCeilingSpeed / 8;  // slows while it crushes
    }
    return true;
}

bool ticMover(Mover& mover, PlaneWorld& world) {
    return std::visit(
        [&](auto& m) {
            using T = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<T, Door>) return ticDoor(m, world);
            else if constexpr (std::is_same_v<T, Plat>) return ticPlat(m, world);
            else if constexpr (std::is_same_v<T, FloorMove>) return ticFloor(m, world);
            else return ticCeiling(m, world);
        },
        mover);
}

int moverSector(const Mover& mover) {
    return std::visit([](const auto& m) { return m.sector; }, mover);
}

}  // namespace penumbra::doom
