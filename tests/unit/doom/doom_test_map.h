// A small Doom map built in memory for the specials tests: room A (sector 0) and room B
// (sector 2) joined by a closed door (sector 1, DR from A, blue-locked DR from B; a switch in A
// opens it too), a raised lift (sector 3) east of B lowered by a repeatable switch in B, and an
// exit switch on the lift's east wall. A blue key lies in B.
#pragma once

#include <map>
#include <utility>

#include "scene/io/wad/map.h"

namespace penumbra::test {

struct DoomTestMap {
    wad::MapData map;
    std::map<std::pair<int, int>, std::uint16_t> vertexIndex;

    std::uint16_t vertex(int x, int y) {
        auto [it, inserted] = vertexIndex.try_emplace({x, y}, std::uint16_t(map.vertices.size()));
        if (inserted) map.vertices.push_back({std::int16_t(x), std::int16_t(y)});
        return it->second;
    }
    std::uint16_t side(int sector, const std::string& upper, const std::string& lower, const std::string& middle) {
        wad::Sidedef s;
        s.upper = upper, s.lower = lower, s.middle = middle, s.sector = std::uint16_t(sector);
        map.sidedefs.push_back(s);
        return std::uint16_t(map.sidedefs.size() - 1);
    }
    // The front sector lies on the right of (x1, y1) -> (x2, y2); back < 0: one-sided.
    std::size_t line(int x1, int y1, int x2, int y2, int front, int back = -1, int special = 0, int tag = 0,
                     const std::string& texture = "STARTAN3") {
        wad::Linedef l;
        l.v1 = vertex(x1, y1);
        l.v2 = vertex(x2, y2);
        l.special = std::uint16_t(special);
        l.tag = std::uint16_t(tag);
        l.flags = back < 0 ? wad::kLineBlocking : wad::kLineTwoSided;
        l.front = back < 0 ? side(front, "-", "-", texture) : side(front, "DOOR3", "STEP1", "-");
        l.back = back < 0 ? wad::kNoSide : side(back, "DOOR3", "STEP1", "-");
        map.linedefs.push_back(l);
        return map.linedefs.size() - 1;
    }
    void sector(int floor, int ceiling, int light, int tag = 0) {
        wad::Sector s;
        s.floorHeight = std::int16_t(floor), s.ceilingHeight = std::int16_t(ceiling);
        s.floorFlat = "FLOOR4_8", s.ceilingFlat = "CEIL3_5";
        s.lightLevel = std::int16_t(light), s.tag = std::uint16_t(tag);
        map.sectors.push_back(s);
    }
};

struct TestLevelMap {
    wad::MapData map;
    std::size_t doorFromA = 0, doorFromB = 0, switchA = 0, liftSwitch = 0, exitSwitch = 0;
};

inline constexpr int kDoorTag = 9, kLiftTag = 5;

inline TestLevelMap doomTestMap() {
    DoomTestMap b;
    b.map.name = "E1M1";
    b.sector(0, 128, 160);            // 0: room A
    b.sector(0, 0, 160, kDoorTag);    // 1: the door, closed
    b.sector(0, 128, 160);            // 2: room B
    b.sector(64, 192, 160, kLiftTag); // 3: the lift, raised
    TestLevelMap t;
    // Room A: x 0..256
    t.switchA = b.line(0, 0, 0, 256, 0, -1, 103, kDoorTag, "SW1STRTN");  // S1 door open
    b.line(0, 256, 256, 256, 0);
    b.line(256, 256, 256, 192, 0);
    t.doorFromA = b.line(256, 192, 256, 64, 0, 1, 1);  // DR door
    b.line(256, 64, 256, 0, 0);
    b.line(256, 0, 0, 0, 0);
    // The door: x 256..272, y 64..192
    b.line(272, 64, 256, 64, 1, -1, 0, 0, "DOORTRAK");
    b.line(256, 192, 272, 192, 1, -1, 0, 0, "DOORTRAK");
    t.doorFromB = b.line(272, 64, 272, 192, 2, 1, 26);  // DR blue door
    // Room B: x 272..528
    b.line(272, 192, 272, 256, 2);
    b.line(272, 256, 528, 256, 2);
    t.liftSwitch = b.line(528, 256, 528, 0, 2, 3, 62, kLiftTag);  // SR lift, on the lift's edge
    b.line(528, 0, 272, 0, 2);
    b.line(272, 0, 272, 64, 2);
    // The lift: x 528..656
    b.line(528, 256, 656, 256, 3);
    t.exitSwitch = b.line(656, 256, 656, 0, 3, -1, 11, 0, "SW1EXIT");  // S1 exit
    b.line(656, 0, 528, 0, 3);
    b.map.things.push_back({64, 128, 0, 1, 7});   // player 1 start in A, facing east
    b.map.things.push_back({400, 200, 0, 5, 7});  // blue card in B
    t.map = std::move(b.map);
    return t;
}

}  // namespace penumbra::test
