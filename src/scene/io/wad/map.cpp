#include "scene/io/wad/map.h"

#include <cmath>

#include "core/error.h"
#include "core/log.h"

namespace penumbra::wad {
namespace {

// The bytes of a map lump and its record count; a missing lump is an error naming it.
struct Records {
    const unsigned char* data = nullptr;
    std::size_t count = 0;
};

Records records(const WadFile& wad, const MapLumps& map, long index, const char* lumpName,
                std::size_t recordBytes) {
    if (index < 0)
        throw Error(wad.fileName() + ": map " + map.name + " has no " + lumpName + " lump");
    std::string_view bytes = wad.lumpData(std::size_t(index), map.name);
    if (bytes.size() % recordBytes != 0)
        logWarning(wad.where(std::size_t(index), map.name) + ": size " +
                   std::to_string(bytes.size()) + " is not a multiple of " +
                   std::to_string(recordBytes) + " bytes; the extra bytes are ignored");
    return {reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size() / recordBytes};
}

// The five map lumps as records, their counts checked: at most what 16-bit indices reach (the
// rest ignored) and what this loader accepts (else an error), and none of the four needed empty.
struct MapRecords {
    Records vertices, linedefs, sidedefs, sectors, things;
};

MapRecords mapRecords(const WadFile& wad, const MapLumps& lumps, const std::string& where) {
    MapRecords r;
    r.vertices = records(wad, lumps, lumps.vertexes, "VERTEXES", kVertexBytes);
    r.linedefs = records(wad, lumps, lumps.linedefs, "LINEDEFS", kLinedefBytes);
    r.sidedefs = records(wad, lumps, lumps.sidedefs, "SIDEDEFS", kSidedefBytes);
    r.sectors = records(wad, lumps, lumps.sectors, "SECTORS", kSectorBytes);
    if (lumps.things >= 0) r.things = records(wad, lumps, lumps.things, "THINGS", kThingBytes);
    // Indices are 16-bit, so records past 65536 (65535 sidedefs) cannot be referenced.
    auto capUnreferenced = [&](Records& rec, std::size_t limit, const char* what) {
        if (rec.count <= limit) return;
        logWarning(where + ": " + std::to_string(rec.count) + " " + what +
                   " records; those past the first " + std::to_string(limit) +
                   " cannot be referenced and are ignored");
        rec.count = limit;
    };
    capUnreferenced(r.vertices, 65536, "VERTEXES");
    capUnreferenced(r.sidedefs, 65535, "SIDEDEFS");
    capUnreferenced(r.sectors, 65536, "SECTORS");
    // Bounds the geometry (and memory) a hostile map can ask for; vanilla maps stay far below.
    if (r.linedefs.count > kMaxLinedefs)
        throw Error(where + ": " + std::to_string(r.linedefs.count) + " linedefs, more than the " +
                    std::to_string(kMaxLinedefs) + " this loader accepts");
    if (r.things.count > kMaxThings)
        throw Error(where + ": " + std::to_string(r.things.count) + " things, more than the " +
                    std::to_string(kMaxThings) + " this loader accepts");
    if (r.vertices.count == 0) throw Error(where + " is empty: it has no vertices");
    if (r.linedefs.count == 0) throw Error(where + " is empty: it has no linedefs");
    if (r.sectors.count == 0) throw Error(where + " is empty: it has no sectors");
    if (r.sidedefs.count == 0) throw Error(where + " is empty: it has no sidedefs");
    return r;
}

std::vector<Vertex> readVertices(const Records& v) {
    std::vector<Vertex> out(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
        const unsigned char* p = v.data + i * kVertexBytes;
        out[i] = {readI16(p), readI16(p + 2)};
    }
    return out;
}

// One line for a record that points past the end of a table the map gives.
void checkReference(const std::string& where, const char* record, std::size_t i, const char* target, std::size_t index,
                    std::size_t count, const char* targets) {
    if (index < count) return;
    throw Error(where + ": " + record + " " + std::to_string(i) + " references " + target + " " + std::to_string(index) +
                ", but the map has " + std::to_string(count) + " " + targets);
}

std::vector<Sector> readSectors(const Records& sec) {
    std::vector<Sector> out(sec.count);
    for (std::size_t i = 0; i < sec.count; ++i) {
        const unsigned char* p = sec.data + i * kSectorBytes;
        Sector& o = out[i];
        o.floorHeight = readI16(p);
        o.ceilingHeight = readI16(p + 2);
        o.floorFlat = readName8(p + 4);
        o.ceilingFlat = readName8(p + 12);
        o.lightLevel = readI16(p + 20);
        o.special = readU16(p + 22);
        o.tag = readU16(p + 24);
    }
    return out;
}

std::vector<Sidedef> readSidedefs(const Records& s, std::size_t sectorCount, const std::string& where) {
    std::vector<Sidedef> out(s.count);
    for (std::size_t i = 0; i < s.count; ++i) {
        const unsigned char* p = s.data + i * kSidedefBytes;
        Sidedef& o = out[i];
        o.xOffset = readI16(p);
        o.yOffset = readI16(p + 2);
        o.upper = readName8(p + 4);
        o.lower = readName8(p + 12);
        o.middle = readName8(p + 20);
        o.sector = readU16(p + 28);
        checkReference(where, "sidedef", i, "sector", o.sector, sectorCount, "sectors");
    }
    return out;
}

// One linedef record, its vertex and sidedef indices checked; a line with only a back side is
// reversed (true), so that its sector lies on the right of v1 -> v2 as for every other line.
bool readLinedef(const unsigned char* p, std::size_t i, const MapRecords& r, const std::string& where,
                 Linedef& o) {
    o.v1 = readU16(p);
    o.v2 = readU16(p + 2);
    o.flags = readU16(p + 4);
    o.special = readU16(p + 6);
    o.tag = readU16(p + 8);
    o.front = readU16(p + 10);
    o.back = readU16(p + 12);
    for (std::uint16_t vi : {o.v1, o.v2}) checkReference(where, "linedef", i, "vertex", vi, r.vertices.count, "vertices");
    for (std::uint16_t si : {o.front, o.back})
        if (si != kNoSide) checkReference(where, "linedef", i, "sidedef", si, r.sidedefs.count, "sidedefs");
    if (o.front != kNoSide || o.back == kNoSide) return false;
    std::swap(o.front, o.back);
    std::swap(o.v1, o.v2);
    return true;
}

std::vector<Linedef> readLinedefs(const MapRecords& r, const std::string& where) {
    std::vector<Linedef> out(r.linedefs.count);
    std::size_t frontless = 0;
    for (std::size_t i = 0; i < r.linedefs.count; ++i)
        if (readLinedef(r.linedefs.data + i * kLinedefBytes, i, r, where, out[i])) ++frontless;
    if (frontless > 0)
        logWarning(where + ": " + std::to_string(frontless) +
                   " linedefs have no front sidedef; they were reversed");
    return out;
}

std::vector<Thing> readThings(const Records& t) {
    std::vector<Thing> out(t.count);
    for (std::size_t i = 0; i < t.count; ++i) {
        const unsigned char* p = t.data + i * kThingBytes;
        out[i] = {readI16(p), readI16(p + 2), readU16(p + 4), readU16(p + 6), readU16(p + 8)};
    }
    return out;
}

}  // namespace

MapData parseMap(const WadFile& wad, const MapLumps& lumps) {
    if (lumps.hexen)
        throw Error(wad.fileName() + ": map " + lumps.name +
                    " is in Hexen format (it has a BEHAVIOR lump), which is not supported");
    const std::string where = wad.fileName() + ": map " + lumps.name;
    const MapRecords r = mapRecords(wad, lumps, where);
    MapData map;
    map.name = lumps.name;
    map.vertices = readVertices(r.vertices);
    map.sectors = readSectors(r.sectors);
    map.sidedefs = readSidedefs(r.sidedefs, r.sectors.count, where);
    map.linedefs = readLinedefs(r, where);
    map.things = readThings(r.things);
    return map;
}

int sectorAt(const MapData& map, double px, double py) {
    double best = INFINITY;
    int sector = -1;
    for (const Linedef& line : map.linedefs) {
        const Vertex& a = map.vertices[line.v1];
        const Vertex& b = map.vertices[line.v2];
        if ((a.y > py) == (b.y > py)) continue;
        double xi = a.x + (py - a.y) * double(b.x - a.x) / double(b.y - a.y);
        if (xi < px || xi >= best) continue;
        best = xi;
        double side = double(b.x - a.x) * (py - a.y) - double(b.y - a.y) * (px - a.x);
        std::uint16_t sd = side < 0 ? line.front : line.back;
        sector = sd != kNoSide ? int(map.sidedefs[sd].sector) : -1;
    }
    return sector;
}

}  // namespace penumbra::wad
