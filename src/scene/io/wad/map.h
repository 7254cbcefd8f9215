// Vanilla Doom map records (VERTEXES, LINEDEFS, SIDEDEFS, SECTORS, THINGS), parsed and checked:
// after parseMap() every index in the map refers to a record that exists.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/io/wad/wad_file.h"

namespace penumbra::wad {

constexpr std::uint16_t kNoSide = 0xFFFF;

struct Vertex {  // 4 bytes on disk
    std::int16_t x = 0, y = 0;
};

enum LinedefFlags : std::uint16_t {
    kLineBlocking = 0x0001,       // ML_BLOCKING: stops players and monsters
    kLineBlockMonsters = 0x0002,  // ML_BLOCKMONSTERS: stops monsters only
    kLineTwoSided = 0x0004,
    kLineUpperUnpegged = 0x0008,
    kLineLowerUnpegged = 0x0010,
};

struct Linedef {  // 14 bytes on disk
    std::uint16_t v1 = 0, v2 = 0, flags = 0, special = 0, tag = 0;
    std::uint16_t front = kNoSide, back = kNoSide;  // sidedef indices; kNoSide = none
};

struct Sidedef {  // 30 bytes on disk
    std::int16_t xOffset = 0, yOffset = 0;
    std::string upper, lower, middle;  // "-" or "" = none
    std::uint16_t sector = 0;
};

struct Sector {  // 26 bytes on disk
    std::int16_t floorHeight = 0, ceilingHeight = 0;
    std::string floorFlat, ceilingFlat;
    std::int16_t lightLevel = 0;
    std::uint16_t special = 0, tag = 0;
};

struct Thing {  // 10 bytes on disk
    std::int16_t x = 0, y = 0;
    std::uint16_t angle = 0, type = 0, flags = 0;
};

constexpr std::size_t kVertexBytes = 4, kLinedefBytes = 14, kSidedefBytes = 30,
                      kSectorBytes = 26, kThingBytes = 10;

constexpr std::size_t kMaxLinedefs = 262144, kMaxThings = 262144;

struct MapData {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<Linedef> linedefs;
    std::vector<Sidedef> sidedefs;
    std::vector<Sector> sectors;
    std::vector<Thing> things;
};

// Reads and validates one map. Throws Error naming the file, map, lump and record on a bad
// index or a lump that does not fit the file; a map without vertices, lines or sectors is an
// error too. Lines without a front side get their back side moved to the front (warning).
MapData parseMap(const WadFile& wad, const MapLumps& lumps);

// The sector containing a point (Doom units): the nearest line crossed by a ray toward +x
// decides, by the side of it the point is on. -1 when the point is outside the map.
int sectorAt(const MapData& map, double x, double y);

}  // namespace penumbra::wad
