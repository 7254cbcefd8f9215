#include "scene/walk/walk_map.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace penumbra::walk {
namespace {

constexpr double kStartCellSize = 128.0;  // Doom's blockmap cell
constexpr std::int64_t kMaxCells = 1 << 20;
constexpr std::int64_t kMaxEntries = 16 << 20;

// Calls cell(column, row) for every grid cell the line passes through (a supercover: per row
// band, the columns between the line's x at the band's edges), slightly conservatively.
template <typename Cell>
void rasterize(const WalkMap& g, const WalkLine& l, Cell&& cell) {
    const double yMin = std::min(l.y1, l.y2), yMax = std::max(l.y1, l.y2);
    const std::int32_t r0 = gridRow(g, yMin), r1 = gridRow(g, yMax);
    const double pad = 1e-9 * g.cellSize;
    for (std::int32_t r = r0; r <= r1; ++r) {
        double xa = std::min(l.x1, l.x2), xb = std::max(l.x1, l.x2);
        if (l.y1 != l.y2) {
            const double bandLo = std::max(yMin, g.originY + r * g.cellSize);
            const double bandHi = std::min(yMax, g.originY + (r + 1) * g.cellSize);
            const double slope = (l.x2 - l.x1) / (l.y2 - l.y1);
            const double xLo = l.x1 + (bandLo - l.y1) * slope, xHi = l.x1 + (bandHi - l.y1) * slope;
            xa = std::min(xLo, xHi);
            xb = std::max(xLo, xHi);
        }
        const std::int32_t c0 = gridColumn(g, xa - pad), c1 = gridColumn(g, xb + pad);
        for (std::int32_t c = c0; c <= c1; ++c) cell(c, r);
    }
}

std::int64_t countEntries(const WalkMap& g) {
    std::int64_t total = 0;
    for (const WalkLine& l : g.lines) {
        rasterize(g, l, [&](std::int32_t, std::int32_t) { ++total; });
        if (total > kMaxEntries) break;
    }
    return total;
}

bool finiteLine(const WalkLine& l) {
    return std::isfinite(l.x1) && std::isfinite(l.y1) && std::isfinite(l.x2) && std::isfinite(l.y2);
}

}  // namespace

std::int32_t gridColumn(const WalkMap& map, double x) {
    const double c = std::floor((x - map.originX) / map.cellSize);
    return std::int32_t(std::clamp(c, 0.0, double(map.columns - 1)));
}

std::int32_t gridRow(const WalkMap& map, double y) {
    const double r = std::floor((y - map.originY) / map.cellSize);
    return std::int32_t(std::clamp(r, 0.0, double(map.rows - 1)));
}

WalkMap makeWalkMap(std::vector<WalkSector> sectors, std::vector<WalkLine> lines) {
    WalkMap g;
    g.sectors = std::move(sectors);
    g.lines = std::move(lines);
    if (g.lines.size() >= std::size_t(UINT32_MAX)) throw Error("walk map: too many lines");
    double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
    for (std::size_t i = 0; i < g.lines.size(); ++i) {
        const WalkLine& l = g.lines[i];
        auto validSector = [&](std::int32_t s) {
            return s >= -1 && s < std::int32_t(g.sectors.size());
        };
        if (!finiteLine(l) || !validSector(l.front) || !validSector(l.back))
            throw Error("walk map: line " + std::to_string(i) +
                        " has a non-finite end or names no sector");
        minX = std::min({minX, l.x1, l.x2}), maxX = std::max({maxX, l.x1, l.x2});
        minY = std::min({minY, l.y1, l.y2}), maxY = std::max({maxY, l.y1, l.y2});
    }
    if (g.lines.empty()) return g;  // columns = 0: every query finds nothing
    g.originX = minX - 1;
    g.originY = minY - 1;
    const double width = maxX - minX + 2, height = maxY - minY + 2;
    g.cellSize = std::max({kStartCellSize, width / 1024.0, height / 1024.0});
    for (;;) {
        g.columns = std::int32_t(std::ceil(width / g.cellSize));
        g.rows = std::int32_t(std::ceil(height / g.cellSize));
        if (std::int64_t(g.columns) * g.rows <= kMaxCells && countEntries(g) <= kMaxEntries) break;
        g.cellSize *= 2;
    }
    const std::size_t cells = std::size_t(g.columns) * std::size_t(g.rows);
    g.cellStart.assign(cells + 1, 0);
    for (const WalkLine& l : g.lines)
        rasterize(g, l, [&](std::int32_t c, std::int32_t r) {
            ++g.cellStart[std::size_t(r) * g.columns + c + 1];
        });
    for (std::size_t c = 0; c < cells; ++c) g.cellStart[c + 1] += g.cellStart[c];
    g.cellLines.resize(g.cellStart[cells]);
    std::vector<std::uint32_t> next(g.cellStart.begin(), g.cellStart.end() - 1);
    for (std::uint32_t i = 0; i < g.lines.size(); ++i)
        rasterize(g, g.lines[i], [&](std::int32_t c, std::int32_t r) {
            g.cellLines[next[std::size_t(r) * g.columns + c]++] = i;
        });
    return g;
}

std::int32_t sectorAt(const WalkMap& map, double px, double py) {
    if (map.columns == 0 || !std::isfinite(px) || !std::isfinite(py)) return -1;
    const double rowY = std::floor((py - map.originY) / map.cellSize);
    if (rowY < 0 || rowY >= map.rows) return -1;
    const std::int32_t row = std::int32_t(rowY);
    double best = INFINITY;
    std::int32_t sector = -1;
    // Cells left to right from the point: a crossing at x lies in x's cell, so once the nearest
    // crossing so far is inside the cells already visited, no later cell can beat it.
    for (std::int32_t c = gridColumn(map, px); c < map.columns; ++c) {
        const std::size_t cell = std::size_t(row) * std::size_t(map.columns) + std::size_t(c);
        for (std::uint32_t k = map.cellStart[cell]; k < map.cellStart[cell + 1]; ++k) {
            const WalkLine& l = map.lines[map.cellLines[k]];
            if ((l.y1 > py) == (l.y2 > py)) continue;
            const double xi = l.x1 + (py - l.y1) * (l.x2 - l.x1) / (l.y2 - l.y1);
            if (xi < px || xi >= best) continue;
            best = xi;
            const double side = (l.x2 - l.x1) * (py - l.y1) - (l.y2 - l.y1) * (px - l.x1);
            sector = side < 0 ? l.front : l.back;
        }
        if (best <= map.originX + (c + 1) * map.cellSize) break;
    }
    return sector;
}

bool lineCrossesBox(const WalkLine& l, double x0, double y0, double x1, double y1) {
    if (std::max(l.x1, l.x2) <= x0 || std::min(l.x1, l.x2) >= x1) return false;
    if (std::max(l.y1, l.y2) <= y0 || std::min(l.y1, l.y2) >= y1) return false;
    // The box's corners must lie strictly on both sides of the line.
    const double dx = l.x2 - l.x1, dy = l.y2 - l.y1;
    bool positive = false, negative = false;
    for (double cx : {x0, x1})
        for (double cy : {y0, y1}) {
            const double side = dx * (cy - l.y1) - dy * (cx - l.x1);
            positive |= side > 0;
            negative |= side < 0;
        }
    return positive && negative;
}

}  // namespace penumbra::walk
