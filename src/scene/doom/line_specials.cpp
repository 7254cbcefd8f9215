#include "scene/doom/line_specials.h"

#include <array>

namespace penumbra::doom {
namespace {

struct Row {
    int number;
    LineSpecial special;
};

constexpr Trigger W = Trigger::Walk, S = Trigger::Switch, G = Trigger::Gun, D = Trigger::Manual;
constexpr bool Once = false, Again = true;
using A = Action;

// Vanilla Doom and Doom II's line types 1-141 (Boom's generalised types are not read).
constexpr Row kRows[] = {
    {1, {D, Again, A::DoorRaise}},      {2, {W, Once, A::DoorOpen}},
    {3, {W, Once, A::DoorClose}},       {4, {W, Once, A::DoorRaise}},
    {5, {W, Once, A::FloorRaiseToLowestCeiling}},
    {6, {W, Once, A::CeilingFastCrushAndRaise}},
    {7, {S, Once, A::BuildStairs}},     {8, {W, Once, A::BuildStairs}},
    {9, {S, Once, A::Donut}},           {10, {W, Once, A::PlatDownWaitUpStay}},
    {11, {S, Once, A::ExitLevel}},      {12, {W, Once, A::LightTurnOnBrightest}},
    {13, {W, Once, A::LightTurnOn255}}, {14, {S, Once, A::PlatRaise32AndChange}},
    {15, {S, Once, A::PlatRaise24AndChange}},
    {16, {W, Once, A::DoorClose30ThenOpen}},
    {17, {W, Once, A::LightStartStrobing}},
    {18, {S, Once, A::FloorRaiseToNearest}},
    {19, {W, Once, A::FloorLowerToHighest}},
    {20, {S, Once, A::PlatRaiseToNearestAndChange}},
    {21, {S, Once, A::PlatDownWaitUpStay}},
    {22, {W, Once, A::PlatRaiseToNearestAndChange}},
    {23, {S, Once, A::FloorLowerToLowest}},
    {24, {G, Once, A::FloorRaiseToLowestCeiling}},
    {25, {W, Once, A::CeilingCrushAndRaise}},
    {26, {D, Again, A::DoorRaise, Key::Blue}},
    {27, {D, Again, A::DoorRaise, Key::Yellow}},
    {28, {D, Again, A::DoorRaise, Key::Red}},
    {29, {S, Once, A::DoorRaise}},      {30, {W, Once, A::FloorRaiseToTexture}},
    {31, {D, Once, A::DoorOpen}},       {32, {D, Once, A::DoorOpen, Key::Blue}},
    {33, {D, Once, A::DoorOpen, Key::Red}},
    {34, {D, Once, A::DoorOpen, Key::Yellow}},
    {35, {W, Once, A::LightTurnOff35}}, {36, {W, Once, A::FloorTurboLower}},
    {37, {W, Once, A::FloorLowerAndChange}},
    {38, {W, Once, A::FloorLowerToLowest}},
    {39, {W, Once, A::Teleport}},       {40, {W, Once, A::CeilingRaiseAndFloorLower}},
    {41, {S, Once, A::CeilingLowerToFloor}},
    {42, {S, Again, A::DoorClose}},     {43, {S, Again, A::CeilingLowerToFloor}},
    {44, {W, Once, A::CeilingLowerAndCrush}},
    {45, {S, Again, A::FloorLowerToHighest}},
    {46, {G, Again, A::DoorOpen}},      {47, {G, Once, A::PlatRaiseToNearestAndChange}},
    {49, {S, Once, A::CeilingCrushAndRaise}},
    {50, {S, Once, A::DoorClose}},      {51, {S, Once, A::SecretExit}},
    {52, {W, Once, A::ExitLevel}},      {53, {W, Once, A::PlatPerpetualRaise}},
    {54, {W, Once, A::PlatStop}},       {55, {S, Once, A::FloorRaiseCrush}},
    {56, {W, Once, A::FloorRaiseCrush}},
    {57, {W, Once, A::CeilingCrushStop}},
    {58, {W, Once, A::FloorRaise24}},   {59, {W, Once, A::FloorRaise24AndChange}},
    {60, {S, Again, A::FloorLowerToLowest}},
    {61, {S, Again, A::DoorOpen}},      {62, {S, Again, A::PlatDownWaitUpStay}},
    {63, {S, Again, A::DoorRaise}},     {64, {S, Again, A::FloorRaiseToLowestCeiling}},
    {65, {S, Again, A::FloorRaiseCrush}},
    {66, {S, Again, A::PlatRaise24AndChange}},
    {67, {S, Again, A::PlatRaise32AndChange}},
    {68, {S, Again, A::PlatRaiseToNearestAndChange}},
    {69, {S, Again, A::FloorRaiseToNearest}},
    {70, {S, Again, A::FloorTurboLower}},
    {71, {S, Once, A::FloorTurboLower}},
    {72, {W, Again, A::CeilingLowerAndCrush}},
    {73, {W, Again, A::CeilingCrushAndRaise}},
    {74, {W, Again, A::CeilingCrushStop}},
    {75, {W, Again, A::DoorClose}},     {76, {W, Again, A::DoorClose30ThenOpen}},
    {77, {W, Again, A::CeilingFastCrushAndRaise}},
    {79, {W, Again, A::LightTurnOff35}},
    {80, {W, Again, A::LightTurnOnBrightest}},
    {81, {W, Again, A::LightTurnOn255}},
    {82, {W, Again, A::FloorLowerToLowest}},
    {83, {W, Again, A::FloorLowerToHighest}},
    {84, {W, Again, A::FloorLowerAndChange}},
    {86, {W, Again, A::DoorOpen}},      {87, {W, Again, A::PlatPerpetualRaise}},
    {88, {W, Again, A::PlatDownWaitUpStay}},
    {89, {W, Again, A::PlatStop}},      {90, {W, Again, A::DoorRaise}},
    {91, {W, Again, A::FloorRaiseToLowestCeiling}},
    {92, {W, Again, A::FloorRaise24}},  {93, {W, Again, A::FloorRaise24AndChange}},
    {94, {W, Again, A::FloorRaiseCrush}},
    {95, {W, Again, A::PlatRaiseToNearestAndChange}},
    {96, {W, Again, A::FloorRaiseToTexture}},
    {97, {W, Again, A::Teleport}},      {98, {W, Again, A::FloorTurboLower}},
    {99, {S, Again, A::DoorBlazeOpen, Key::Blue}},
    {100, {W, Once, A::BuildStairsTurbo}},
    {101, {S, Once, A::FloorRaiseToLowestCeiling}},
    {102, {S, Once, A::FloorLowerToHighest}},
    {103, {S, Once, A::DoorOpen}},
    {104, {W, Once, A::LightTurnOffDimmest}},
    {105, {W, Again, A::DoorBlazeRaise}},
    {106, {W, Again, A::DoorBlazeOpen}},
    {107, {W, Again, A::DoorBlazeClose}},
    {108, {W, Once, A::DoorBlazeRaise}},
    {109, {W, Once, A::DoorBlazeOpen}},
    {110, {W, Once, A::DoorBlazeClose}},
    {111, {S, Once, A::DoorBlazeRaise}},
    {112, {S, Once, A::DoorBlazeOpen}},
    {113, {S, Once, A::DoorBlazeClose}},
    {114, {S, Again, A::DoorBlazeRaise}},
    {115, {S, Again, A::DoorBlazeOpen}},
    {116, {S, Again, A::DoorBlazeClose}},
    {117, {D, Again, A::DoorBlazeRaise}},
    {118, {D, Once, A::DoorBlazeOpen}},
    {119, {W, Once, A::FloorRaiseToNearest}},
    {120, {W, Again, A::PlatBlazeDownWaitUpStay}},
    {121, {W, Once, A::PlatBlazeDownWaitUpStay}},
    {122, {S, Once, A::PlatBlazeDownWaitUpStay}},
    {123, {S, Again, A::PlatBlazeDownWaitUpStay}},
    {124, {W, Once, A::SecretExit}},
    {125, {W, Once, A::Teleport}},      {126, {W, Again, A::Teleport}},
    {127, {S, Once, A::BuildStairsTurbo}},
    {128, {W, Again, A::FloorRaiseToNearest}},
    {129, {W, Again, A::FloorRaiseTurbo}},
    {130, {W, Once, A::FloorRaiseTurbo}},
    {131, {S, Once, A::FloorRaiseTurbo}},
    {132, {S, Again, A::FloorRaiseTurbo}},
    {133, {S, Once, A::DoorBlazeOpen, Key::Blue}},
    {134, {S, Again, A::DoorBlazeOpen, Key::Red}},
    {135, {S, Once, A::DoorBlazeOpen, Key::Red}},
    {136, {S, Again, A::DoorBlazeOpen, Key::Yellow}},
    {137, {S, Once, A::DoorBlazeOpen, Key::Yellow}},
    {138, {S, Again, A::LightTurnOn255}},
    {139, {S, Again, A::LightTurnOff35}},
    {140, {S, Once, A::FloorRaise512}},
    {141, {W, Once, A::CeilingSilentCrushAndRaise}},
};

}  // namespace

std::optional<LineSpecial> lineSpecial(int number) {
    for (const Row& row : kRows)
        if (row.number == number) return row.special;
    return std::nullopt;
}

Key keyOfThing(int type) {
    switch (type) {
        case 5: case 40: return Key::Blue;
        case 6: case 39: return Key::Yellow;
        case 13: case 38: return Key::Red;
        default: return Key::None;
    }
}

}  // namespace penumbra::doom
