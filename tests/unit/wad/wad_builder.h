// Builds small WAD files in memory for tests and the fuzz corpus.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace penumbra::testing {

inline void put16(std::string& s, int v) {
    s.push_back(char(v & 0xFF));
    s.push_back(char((v >> 8) & 0xFF));
}
inline void put32(std::string& s, std::int64_t v) {
    for (int i = 0; i < 4; ++i) s.push_back(char((v >> (8 * i)) & 0xFF));
}
inline void putName(std::string& s, const std::string& name) {
    for (std::size_t i = 0; i < 8; ++i) s.push_back(i < name.size() ? name[i] : '\0');
}

struct WadBuilder {
    std::vector<std::pair<std::string, std::string>> lumps;

    void add(const std::string& name, std::string bytes = {}) { lumps.emplace_back(name, std::move(bytes)); }

    // Header, lump data, then the directory (as id's tools write it).
    std::string build(const char* magic = "PWAD") const {
        std::string out(magic, 4);
        std::string data, dir;
        for (const auto& [name, bytes] : lumps) {
            put32(dir, 12 + std::int64_t(data.size()));
            put32(dir, std::int64_t(bytes.size()));
            putName(dir, name);
            data += bytes;
        }
        put32(out, std::int64_t(lumps.size()));
        put32(out, 12 + std::int64_t(data.size()));
        return out + data + dir;
    }
};

struct MapBuilder {
    std::string vertexes, linedefs, sidedefs, sectors, things;
    int vertexCount = 0, sideCount = 0, sectorCount = 0;

    int vertex(int x, int y) {
        put16(vertexes, x);
        put16(vertexes, y);
        return vertexCount++;
    }
    int sector(int floor, int ceiling, const std::string& floorFlat, const std::string& ceilFlat,
               int light) {
        put16(sectors, floor);
        put16(sectors, ceiling);
        putName(sectors, floorFlat);
        putName(sectors, ceilFlat);
        put16(sectors, light);
        put16(sectors, 0);
        put16(sectors, 0);
        return sectorCount++;
    }
    int side(int sector, const std::string& upper, const std::string& lower,
             const std::string& middle, int xOff = 0, int yOff = 0) {
        put16(sidedefs, xOff);
        put16(sidedefs, yOff);
        putName(sidedefs, upper);
        putName(sidedefs, lower);
        putName(sidedefs, middle);
        put16(sidedefs, sector);
        return sideCount++;
    }
    void line(int v1, int v2, int front, int back = 0xFFFF, int flags = 1) {
        put16(linedefs, v1);
        put16(linedefs, v2);
        put16(linedefs, flags);
        put16(linedefs, 0);
        put16(linedefs, 0);
        put16(linedefs, front);
        put16(linedefs, back);
    }
    void thing(int x, int y, int angle, int type) {
        put16(things, x);
        put16(things, y);
        put16(things, angle);
        put16(things, type);
        put16(things, 7);
    }
    // A closed one-sided loop through the points, all sides facing `sector`.
    void loop(const std::vector<std::pair<int, int>>& pts, int sector, const std::string& tex) {
        int first = -1, prev = -1;
        for (auto [x, y] : pts) {
            int v = vertex(x, y);
            if (prev >= 0) line(prev, v, side(sector, "-", "-", tex));
            if (first < 0) first = v;
            prev = v;
        }
        line(prev, first, side(sector, "-", "-", tex));
    }
    void addTo(WadBuilder& wad, const std::string& name) const {
        wad.add(name);
        wad.add("THINGS", things);
        wad.add("LINEDEFS", linedefs);
        wad.add("SIDEDEFS", sidedefs);
        wad.add("VERTEXES", vertexes);
        wad.add("SECTORS", sectors);
    }
};

// PLAYPAL (a colour ramp), one 8x8 patch (rows 6 and 7 transparent), the 16x16 texture WALL1
// made of two copies of it, the 16x32 texture TALL1, and the flats FLOOR1 and CEIL1.
inline void addTestGraphics(WadBuilder& wad, bool withFlats = true) {
    std::string pal;
    for (int i = 0; i < 256; ++i) {
        pal.push_back(char(i));
        pal.push_back(char(255 - i));
        pal.push_back(char(i / 2));
    }
    wad.add("PLAYPAL", pal);
    std::string pnames;
    put32(pnames, 1);
    putName(pnames, "PATCH1");
    wad.add("PNAMES", pnames);
    std::string tex;
    put32(tex, 2);
    put32(tex, 12);
    put32(tex, 12 + 22 + 20);
    auto def = [&](const char* name, int w, int h, std::vector<std::pair<int, int>> origins) {
        putName(tex, name);
        put32(tex, 0);
        put16(tex, w);
        put16(tex, h);
        put32(tex, 0);
        put16(tex, int(origins.size()));
        for (auto [x, y] : origins) {
            put16(tex, x);
            put16(tex, y);
            put16(tex, 0);
            put16(tex, 1);
            put16(tex, 0);
        }
    };
    def("WALL1", 16, 16, {{0, 0}, {8, 8}});
    def("TALL1", 16, 32, {{0, 0}});
    wad.add("TEXTURE1", tex);
    wad.add("P_START");
    std::string patch;
    put16(patch, 8);
    put16(patch, 8);
    put16(patch, 0);
    put16(patch, 0);
    for (int x = 0; x < 8; ++x) put32(patch, 8 + 32 + x * 11);
    for (int x = 0; x < 8; ++x) {
        patch.push_back(0);  // top
        patch.push_back(6);  // length
        patch.push_back(0);
        for (int y = 0; y < 6; ++y) patch.push_back(char(16 * x + y + 1));
        patch.push_back(0);
        patch.push_back(char(0xFF));
    }
    wad.add("PATCH1", patch);
    wad.add("P_END");
    if (withFlats) {
        wad.add("F_START");
        wad.add("FLOOR1", std::string(4096, char(40)));
        wad.add("CEIL1", std::string(4096, char(80)));
        wad.add("F_END");
    }
}

// A 256x256 room (sector 0: floor 0, ceiling 128) with a 64x64 pillar in its middle
// (96..160), the player at (64, 64) facing north and a floor lamp at (200, 200).
inline MapBuilder roomWithPillar() {
    MapBuilder m;
    int s = m.sector(0, 128, "FLOOR1", "CEIL1", 160);
    m.loop({{0, 0}, {0, 256}, {256, 256}, {256, 0}}, s, "WALL1");
    m.loop({{96, 96}, {160, 96}, {160, 160}, {96, 160}}, s, "WALL1");
    m.thing(64, 64, 90, 1);
    m.thing(200, 200, 0, 2028);
    return m;
}

// A picture-format lump (patch or sprite frame): index(x, y) is the palette index of each texel,
// or -1 where it is transparent. Heights up to 254.
inline std::string picture(int width, int height, const std::function<int(int, int)>& index, int left = 0,
                           int top = 0) {
    std::vector<std::string> columns(static_cast<std::size_t>(width));
    for (int x = 0; x < width; ++x) {
        std::string& c = columns[std::size_t(x)];
        for (int y = 0; y < height;) {
            if (index(x, y) < 0) {
                ++y;
                continue;
            }
            int end = y;
            while (end < height && index(x, end) >= 0) ++end;
            c.push_back(char(y));
            c.push_back(char(end - y));
            c.push_back(0);
            for (int k = y; k < end; ++k) c.push_back(char(index(x, k)));
            c.push_back(0);
            y = end;
        }
        c.push_back(char(0xFF));
    }
    std::string out;
    put16(out, width);
    put16(out, height);
    put16(out, left);
    put16(out, top);
    std::size_t offset = 8 + 4 * std::size_t(width);
    for (const std::string& c : columns) {
        put32(out, std::int64_t(offset));
        offset += c.size();
    }
    for (const std::string& c : columns) out += c;
    return out;
}

// Graphics with names of one's choosing: PLAYPAL (a given palette, or addTestGraphics' ramp),
// wall textures made of one patch each, flats and sprite frames.
struct Graphics {
    std::string palette;  // 768 bytes; empty: the ramp (i, 255 - i, i / 2)
    std::vector<std::pair<std::string, std::string>> patches;   // name, picture lump
    std::vector<std::pair<std::string, std::string>> flats;     // name, 4096 palette indices
    std::vector<std::pair<std::string, std::string>> sprites;   // lump name, picture lump

    // A wall texture `name` that is the patch `picture` (of its own size) at the origin.
    void texture(const std::string& name, std::string pictureLump) { patches.emplace_back(name, std::move(pictureLump)); }
    void flat(const std::string& name, const std::function<int(int, int)>& index) {
        std::string f(4096, '\0');
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) f[std::size_t(y * 64 + x)] = char(index(x, y));
        flats.emplace_back(name, f);
    }

    void addTo(WadBuilder& wad) const {
        std::string pal = palette;
        if (pal.empty())
            for (int i = 0; i < 256; ++i) pal += {char(i), char(255 - i), char(i / 2)};
        wad.add("PLAYPAL", pal);
        std::string pnames, tex;
        put32(pnames, std::int64_t(patches.size()));
        for (const auto& p : patches) putName(pnames, p.first);
        wad.add("PNAMES", pnames);
        put32(tex, std::int64_t(patches.size()));
        for (std::size_t i = 0; i < patches.size(); ++i) put32(tex, 4 + 4 * std::int64_t(patches.size()) + 32 * std::int64_t(i));
        for (std::size_t i = 0; i < patches.size(); ++i) {
            const std::string& lump = patches[i].second;
            const int w = int(std::uint8_t(lump[0])) | (int(std::uint8_t(lump[1])) << 8);
            const int h = int(std::uint8_t(lump[2])) | (int(std::uint8_t(lump[3])) << 8);
            putName(tex, patches[i].first);
            put32(tex, 0);
            put16(tex, w);
            put16(tex, h);
            put32(tex, 0);
            put16(tex, 1);
            put16(tex, 0);
            put16(tex, 0);
            put16(tex, int(i));
            put16(tex, 1);
            put16(tex, 0);
        }
        wad.add("TEXTURE1", tex);
        wad.add("P_START");
        for (const auto& p : patches) wad.add(p.first, p.second);
        wad.add("P_END");
        wad.add("F_START");
        for (const auto& f : flats) wad.add(f.first, f.second);
        wad.add("F_END");
        wad.add("S_START");
        for (const auto& sp : sprites) wad.add(sp.first, sp.second);
        wad.add("S_END");
    }
};

}  // namespace penumbra::testing
