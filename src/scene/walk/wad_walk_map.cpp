#include "scene/walk/wad_walk_map.h"

namespace penumbra::walk {

WalkMap buildWalkMap(const wad::MapData& map) {
    std::vector<WalkSector> sectors;
    sectors.reserve(map.sectors.size());
    for (const wad::Sector& s : map.sectors)
        sectors.push_back({double(s.floorHeight), double(s.ceilingHeight)});
    // parseMap checked every index, so sides and sectors exist.
    auto sectorOf = [&](std::uint16_t side) {
        return side == wad::kNoSide ? -1 : std::int32_t(map.sidedefs[side].sector);
    };
    std::vector<WalkLine> lines;
    lines.reserve(map.linedefs.size());
    for (const wad::Linedef& l : map.linedefs) {
        const wad::Vertex& a = map.vertices[l.v1];
        const wad::Vertex& b = map.vertices[l.v2];
        if (a.x == b.x && a.y == b.y) continue;
        WalkLine w;
        w.x1 = a.x, w.y1 = a.y, w.x2 = b.x, w.y2 = b.y;
        w.front = sectorOf(l.front);
        w.back = sectorOf(l.back);
        w.blocking = (l.flags & wad::kLineBlocking) != 0;
        lines.push_back(w);
    }
    return makeWalkMap(std::move(sectors), std::move(lines));
}

}  // namespace penumbra::walk
