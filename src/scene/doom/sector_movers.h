// Doom's moving sectors as state machines stepped once per tic (35 a second): doors, platforms
// (lifts), floors and ceilings (crushers). Speeds, waits and the choices at each end follow id
// Software's p_doors.c, p_plats.c, p_floor.c and p_ceilng.c (T_VerticalDoor, T_PlatRaise,
// T_MoveFloor, T_MoveCeiling over T_MovePlane); the code is our own. Heights are map units.
#pragma once

#include <variant>

namespace penumbra::doom {

constexpr int kTicsPerSecond = 35;
constexpr double kDoorSpeed = 2;      // VDOORSPEED: units per tic
constexpr int kDoorWait = 150;        // VDOORWAIT: tics a raised door stays open
constexpr double kPlatSpeed = 1;      // PLATSPEED; lifts move at 4x
constexpr int kPlatWait = 3 * kTicsPerSecond;  // PLATWAIT seconds: 105 tics at the bottom
constexpr double kFloorSpeed = 1;     // FLOORSPEED
constexpr double kCeilingSpeed = 1;   // CEILSPEED
constexpr int kClose30Wait = 30 * kTicsPerSecond;

enum class Plane { Floor, Ceiling };

// What the movers move: the sectors' heights, and whether whatever stands in a sector still fits
// after it moved (Doom's P_ChangeSector). Implemented by the level (level.cpp) and by tests.
class PlaneWorld {
public:
    virtual ~PlaneWorld() = default;
    virtual double height(int sector, Plane plane) const = 0;
    virtual void setHeight(int sector, Plane plane, double height) = 0;
    virtual bool thingsFit(int sector) const = 0;
};

enum class MoveResult { Moved, Crushed, PastDest };

// One tic of a plane moving by `speed` toward `dest` (direction +1 up, -1 down): it stops at
// dest (PastDest); a move that squeezes a thing is undone (Crushed) unless `crush` is set (then
// it stays moved and still reports Crushed). A floor going down or a ceiling going up never
// squeezes anything.
MoveResult movePlane(PlaneWorld& world, int sector, Plane plane, double speed, double dest, bool crush,
                     int direction);

enum class DoorKind { Normal, Close30ThenOpen, Close, Open, BlazeRaise, BlazeOpen, BlazeClose };

struct Door {
    DoorKind kind = DoorKind::Normal;
    int sector = 0;
    double topHeight = 0;
    double speed = kDoorSpeed;
    int direction = 1;  // 1 up, -1 down, 0 waiting at the top (or closed, for Close30ThenOpen)
    int topWait = kDoorWait;
    int countdown = 0;
};

enum class PlatKind { PerpetualRaise, DownWaitUpStay, BlazeDownWaitUpStay, RaiseAndChange, RaiseToNearestAndChange };
enum class PlatStatus { Up, Down, Waiting };

struct Plat {
    PlatKind kind = PlatKind::DownWaitUpStay;
    int sector = 0;
    double low = 0, high = 0, speed = kPlatSpeed * 4;
    int wait = kPlatWait, count = 0;
    PlatStatus status = PlatStatus::Down;
    bool crush = false;
    bool inStasis = false;  // stopped by a "stop" line; a perpetual lift line restarts it
    PlatStatus oldStatus = PlatStatus::Down;
};

struct FloorMove {
    int sector = 0;
    double dest = 0, speed = kFloorSpeed;
    int direction = 1;
    bool crush = false;
};

enum class CeilingKind { LowerToFloor, RaiseToHighest, LowerAndCrush, CrushAndRaise, FastCrushAndRaise, SilentCrushAndRaise };

struct CeilingMove {
    CeilingKind kind = CeilingKind::CrushAndRaise;
    int sector = 0;
    double bottomHeight = 0, topHeight = 0, speed = kCeilingSpeed;
    int direction = -1;
    bool crush = false;
    bool inStasis = false;
    int oldDirection = -1;
};

using Mover = std::variant<Door, Plat, FloorMove, CeilingMove>;

// One tic of a mover; false once it has finished (the sector is free for another mover).
bool ticDoor(Door& door, PlaneWorld& world);
bool ticPlat(Plat& plat, PlaneWorld& world);
bool ticFloor(FloorMove& floor, PlaneWorld& world);
bool ticCeiling(CeilingMove& ceiling, PlaneWorld& world);
bool ticMover(Mover& mover, PlaneWorld& world);
int moverSector(const Mover& mover);

}  // namespace penumbra::doom
