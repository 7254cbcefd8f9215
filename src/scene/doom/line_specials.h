// What vanilla Doom's linedef specials do, by number (Doom and Doom II's p_spec.c, p_switch.c
// and p_doors.c; the Doom wiki's "Linedef type" table): how a line is triggered, whether it
// works again, the action on its tagged sectors (or, for manual doors, on the sector behind it),
// and the key it needs. docs/VIEWER.md lists which actions are supported.
#pragma once

#include <optional>

namespace penumbra::doom {

enum class Trigger {
    Walk,    // W: the player's centre crosses the line
    Switch,  // S: used from the front (a switch; its SW1/SW2 texture turns)
    Gun,     // G: shot
    Manual,  // D: used from the front; moves the sector behind the line (doors)
};

enum class Key { None, Blue, Yellow, Red };

enum class Action {
    // doors (tagged sectors, or the back sector for Manual)
    DoorRaise, DoorOpen, DoorClose, DoorClose30ThenOpen, DoorBlazeRaise, DoorBlazeOpen, DoorBlazeClose,
    // platforms
    PlatDownWaitUpStay, PlatBlazeDownWaitUpStay, PlatPerpetualRaise, PlatStop, PlatRaiseToNearestAndChange,
    PlatRaise24AndChange, PlatRaise32AndChange,
    // floors
    FloorLowerToHighest, FloorLowerToLowest, FloorTurboLower, FloorRaiseToLowestCeiling, FloorRaiseCrush,
    FloorRaiseToNearest, FloorRaiseTurbo, FloorRaise24, FloorRaise24AndChange, FloorRaise512,
    FloorLowerAndChange, FloorRaiseToTexture,
    // ceilings
    CeilingLowerToFloor, CeilingRaiseToHighest, CeilingLowerAndCrush, CeilingCrushAndRaise,
    CeilingFastCrushAndRaise, CeilingSilentCrushAndRaise, CeilingCrushStop, CeilingRaiseAndFloorLower,
    // lights
    LightTurnOn255, LightTurnOnBrightest, LightTurnOff35, LightTurnOffDimmest, LightStartStrobing,
    // the level
    ExitLevel, SecretExit,
    // recognised, not done (docs/VIEWER.md): the player is not moved, no stairs or donuts
    Teleport, BuildStairs, BuildStairsTurbo, Donut, Unsupported,
};

struct LineSpecial {
    Trigger trigger = Trigger::Walk;
    bool repeat = false;
    Action action = Action::Unsupported;
    Key key = Key::None;
};

// The special with this number, or none for 0 and numbers vanilla Doom does not define.
std::optional<LineSpecial> lineSpecial(int number);

// The key a thing of this type is (Doom's cards and skulls: a skull opens what a card of its
// colour opens); Key::None for every other thing.
Key keyOfThing(int type);

}  // namespace penumbra::doom
