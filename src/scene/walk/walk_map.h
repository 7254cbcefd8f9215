// What walking collides with: a level's lines with the floor and ceiling heights of the sectors
// on their two sides, in the level's own map units (Doom: x east, y north, z up; see
// scene/io/wad/units.h for how they sit in the scene), plus a uniform grid over the lines (like
// Doom's blockmap) so a query touches only the lines near it. Plain data, no GPU or window.
#pragma once

#include <cstdint>
#include <vector>

namespace penumbra::walk {

struct WalkSector {
    double floor = 0, ceiling = 0;  // heights, map units
};

struct WalkLine {
    double x1 = 0, y1 = 0, x2 = 0, y2 = 0;
    std::int32_t front = -1, back = -1;  // sector on each side; -1: none (a one-sided wall)
    bool blocking = false;               // Doom's ML_BLOCKING: stops the player even when two-sided

    bool impassable() const { return front < 0 || back < 0 || blocking; }
};

struct WalkMap {
    std::vector<WalkSector> sectors;
    std::vector<WalkLine> lines;
    // The grid: cell (column, row) covers [originX + column * cellSize, + cellSize) x the same in
    // y, and lists every line that passes through it (cellLines[cellStart[c] .. cellStart[c+1])).
    double originX = 0, originY = 0, cellSize = 1;
    std::int32_t columns = 0, rows = 0;
    std::vector<std::uint32_t> cellStart;
    std::vector<std::uint32_t> cellLines;
};

// Builds the grid over the lines. Sector indices must be -1 or name a sector (checked: Error).
// Cells start at 128 units (Doom's blockmap) and grow until the grid stays small (at most about a
// million cells and 16 million entries), so no input can make it unbounded.
WalkMap makeWalkMap(std::vector<WalkSector> sectors, std::vector<WalkLine> lines);

// The sector containing a point: the nearest line crossed by a ray towards +x decides, by the
// side of it the point is on (the WAD loader's rule). -1 outside the map.
std::int32_t sectorAt(const WalkMap& map, double x, double y);

// Calls visit(lineIndex) for every line in the grid cells that the box [x0, x1] x [y0, y1]
// touches (a line may come more than once, and lines near the box too).
template <typename Visit>
void forEachLineNear(const WalkMap& map, double x0, double y0, double x1, double y1, Visit&& visit);

// Whether a line passes through the inside of the box (touching its edge does not count).
bool lineCrossesBox(const WalkLine& line, double x0, double y0, double x1, double y1);

// ---- implementation of the template ----
std::int32_t gridColumn(const WalkMap& map, double x);  // clamped to the grid
std::int32_t gridRow(const WalkMap& map, double y);

template <typename Visit>
void forEachLineNear(const WalkMap& map, double x0, double y0, double x1, double y1,
                     Visit&& visit) {
    if (map.columns == 0 || !(x0 <= x1) || !(y0 <= y1)) return;
    const std::int32_t c0 = gridColumn(map, x0), c1 = gridColumn(map, x1);
    const std::int32_t r0 = gridRow(map, y0), r1 = gridRow(map, y1);
    for (std::int32_t r = r0; r <= r1; ++r)
        for (std::int32_t c = c0; c <= c1; ++c) {
            const std::size_t cell = std::size_t(r) * std::size_t(map.columns) + std::size_t(c);
            for (std::uint32_t k = map.cellStart[cell]; k < map.cellStart[cell + 1]; ++k)
                visit(map.cellLines[k]);
        }
}

}  // namespace penumbra::walk
