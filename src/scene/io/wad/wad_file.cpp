#include "scene/io/wad/wad_file.h"

#include <algorithm>
#include <array>
#include <cctype>

#include "core/error.h"

namespace penumbra::wad {

std::string readName8(const unsigned char* p) {
    std::string name;
    for (int i = 0; i < 8 && p[i] != 0; ++i) {
        unsigned char c = p[i];
        name.push_back(c >= 32 && c < 127 ? char(std::toupper(c)) : '?');
    }
    return name;
}

WadFile::WadFile(std::string_view bytes, std::string fileName)
    : bytes_(bytes), fileName_(std::move(fileName)) {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes_.data());
    if (bytes_.size() < 12)
        throw Error(fileName_ + ": not a WAD file (" + std::to_string(bytes_.size()) +
                    " bytes, shorter than the 12-byte header)");
    std::string_view magic = bytes_.substr(0, 4);
    if (magic != "IWAD" && magic != "PWAD")
        throw Error(fileName_ + ": not a WAD file (the header does not start with IWAD or PWAD)");
    std::int64_t count = readI32(data + 4);
    std::int64_t dirOffset = readI32(data + 8);
    const std::int64_t fileSize = std::int64_t(bytes_.size());
    // Each directory entry takes 16 bytes of the file, so the count is bounded by the size.
    if (count < 0 || count > (fileSize - 12) / 16)
        throw Error(fileName_ + ": absurd lump count " + std::to_string(count) + " for a file of " +
                    std::to_string(fileSize) + " bytes");
    if (dirOffset < 0 || dirOffset > fileSize || count * 16 > fileSize - dirOffset)
        throw Error(fileName_ + ": the lump directory (" + std::to_string(count) +
                    " entries at offset " + std::to_string(dirOffset) +
                    ") ends past the end of the file (truncated directory?)");
    lumps_.reserve(std::size_t(count));
    for (std::int64_t i = 0; i < count; ++i) {
        const unsigned char* e = data + dirOffset + 16 * i;
        LumpEntry entry;
        entry.offset = readI32(e);
        entry.size = readI32(e + 4);
        entry.name = readName8(e + 8);
        lumps_.push_back(std::move(entry));
    }
}

std::string WadFile::where(std::size_t index, std::string_view context) const {
    std::string s = fileName_ + ": lump " + (index < lumps_.size() ? lumps_[index].name : "?");
    if (!context.empty()) s += " of " + std::string(context);
    return s;
}

std::string_view WadFile::lumpData(std::size_t index, std::string_view context) const {
    PN_CHECK(index < lumps_.size());
    const LumpEntry& e = lumps_[index];
    const std::int64_t fileSize = std::int64_t(bytes_.size());
    if (e.size == 0) return {};
    if (e.size < 0)
        throw Error(where(index, context) + " has a negative size (" + std::to_string(e.size) + ")");
    if (e.offset < 0 || e.offset > fileSize)
        throw Error(where(index, context) + " starts past the end of the file (offset " +
                    std::to_string(e.offset) + ", file size " + std::to_string(fileSize) + ")");
    if (e.size > fileSize - e.offset)
        throw Error(where(index, context) + " ends past the end of the file");
    return bytes_.substr(std::size_t(e.offset), std::size_t(e.size));
}

long WadFile::findLast(std::string_view name, std::size_t first, std::size_t last) const {
    last = std::min(last, lumps_.size());
    for (std::size_t i = last; i > first; --i)
        if (lumps_[i - 1].name == name) return long(i - 1);
    return -1;
}

std::vector<std::pair<std::size_t, std::size_t>> WadFile::markerRanges(std::string_view startA,
                                                                       std::string_view endA,
                                                                       std::string_view startB,
                                                                       std::string_view endB) const {
    std::vector<std::pair<std::size_t, std::size_t>> ranges;
    for (std::size_t i = 0; i < lumps_.size(); ++i) {
        const std::string& n = lumps_[i].name;
        bool isA = n == startA, isB = n == startB;
        if (!isA && !isB) continue;
        std::size_t j = i + 1;
        // Nested markers (FF_START inside F_START) are skipped over; the outer END closes.
        while (j < lumps_.size() && lumps_[j].name != endA && lumps_[j].name != endB) ++j;
        ranges.emplace_back(i + 1, j);
        i = j;  // continue after the END marker
    }
    return ranges;
}

std::vector<MapLumps> findMaps(const WadFile& wad) {
    static constexpr std::array<std::string_view, 12> kMapLumps = {
        "THINGS", "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS",     "SSECTORS",
        "NODES",  "SECTORS",  "REJECT",   "BLOCKMAP", "BEHAVIOR", "SCRIPTS"};
    auto isMapLump = [](const std::string& n) {
        return std::find(kMapLumps.begin(), kMapLumps.end(), n) != kMapLumps.end();
    };
    const auto& lumps = wad.lumps();
    std::vector<MapLumps> maps;
    for (std::size_t i = 0; i + 1 < lumps.size(); ++i) {
        if (isMapLump(lumps[i].name)) continue;
        if (lumps[i + 1].name != "THINGS" && lumps[i + 1].name != "LINEDEFS") continue;
        MapLumps m;
        m.name = lumps[i].name;
        std::size_t j = i + 1;
        for (; j < lumps.size() && j <= i + kMapLumps.size() && isMapLump(lumps[j].name); ++j) {
            const std::string& n = lumps[j].name;
            long* slot = n == "THINGS"     ? &m.things
                         : n == "LINEDEFS" ? &m.linedefs
                         : n == "SIDEDEFS" ? &m.sidedefs
                         : n == "VERTEXES" ? &m.vertexes
                         : n == "SECTORS"  ? &m.sectors
                                           : nullptr;
            if (slot && *slot < 0) *slot = long(j);
            if (n == "BEHAVIOR") m.hexen = true;
        }
        maps.push_back(std::move(m));
        i = j - 1;
    }
    return maps;
}

}  // namespace penumbra::wad
