// Sector floors and ceilings: the boundary of each sector as directed edges (sector on the
// right, as Doom's front sides are), open chains closed, then filled by a sweep over vertical
// slabs with the nonzero winding rule. The sweep needs no simple polygons: holes, several outer
// polygons, touching loops and even crossing lines all come out with the right area.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/io/wad/map.h"

namespace penumbra::wad {

struct Point2 {
    double x = 0, y = 0;
};

struct Edge2 {
    Point2 a, b;  // directed: the sector lies on the right of a -> b
};

struct SectorOutline {
    std::vector<Edge2> edges;  // closed: every vertex has as many edges in as out
    int closedChains = 0;      // open chains that were closed with a straight edge
};

// One outline per sector. Lines with the same sector on both sides and zero-length lines are
// left out (they bound nothing).
std::vector<SectorOutline> buildSectorOutlines(const MapData& map);

using Triangle2 = std::array<Point2, 3>;

// Appends triangles covering the points of nonzero winding number. `budget` counts work units
// (edge visits); returns false, leaving `out` as it was, once it would run out (hostile input).
bool fillNonzero(const std::vector<Edge2>& edges, std::vector<Triangle2>& out,
                 std::int64_t& budget);

}  // namespace penumbra::wad
