// The WAD container: a 12-byte header and a directory of named lumps. Every offset and size is
// checked against the file before a lump's bytes are handed out.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::wad {

struct LumpEntry {
    std::string name;  // upper case, at most 8 characters, printable
    std::int64_t offset = 0;
    std::int64_t size = 0;
};

// Little-endian readers; callers check bounds first.
inline std::uint16_t readU16(const unsigned char* p) {
    return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
inline std::int16_t readI16(const unsigned char* p) { return static_cast<std::int16_t>(readU16(p)); }
inline std::int32_t readI32(const unsigned char* p) {
    return static_cast<std::int32_t>(std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) |
                                     (std::uint32_t(p[2]) << 16) | (std::uint32_t(p[3]) << 24));
}
// An 8-byte, NUL-padded lump or texture name: upper case, stops at the first NUL, and any
// non-printable byte becomes '?' so it can go into a message.
std::string readName8(const unsigned char* p);

class WadFile {
public:
    // `fileName` is used in every message. Throws Error for a bad header or directory.
    WadFile(std::string_view bytes, std::string fileName);

    const std::string& fileName() const { return fileName_; }
    const std::vector<LumpEntry>& lumps() const { return lumps_; }
    std::size_t size() const { return bytes_.size(); }

    // The bytes of lump `index`; throws Error "<file>: lump NAME[ of MAP] ends past the end of the
    // file" (or starts past it, or has a negative size). `context` is e.g. "E1M1" or "".
    std::string_view lumpData(std::size_t index, std::string_view context = {}) const;

    // Index of the last lump called `name`, searching [first, last); -1 when none.
    long findLast(std::string_view name, std::size_t first = 0, std::size_t last = SIZE_MAX) const;
    // The lumps between a START and END marker pair (e.g. F_START..F_END, also FF_START..FF_END):
    // every [begin, end) range found.
    std::vector<std::pair<std::size_t, std::size_t>> markerRanges(std::string_view startA,
                                                                  std::string_view endA,
                                                                  std::string_view startB,
                                                                  std::string_view endB) const;
    // Where a message should point: "<file>: lump NAME of E1M1".
    std::string where(std::size_t index, std::string_view context = {}) const;

private:
    std::string_view bytes_;
    std::string fileName_;
    std::vector<LumpEntry> lumps_;
};

// The lumps of one map: indices into the directory, -1 when absent.
struct MapLumps {
    std::string name;
    long things = -1, linedefs = -1, sidedefs = -1, vertexes = -1, sectors = -1;
    bool hexen = false;  // has a BEHAVIOR lump: Hexen format, which we do not read
};

// Map markers: a lump followed by THINGS (or LINEDEFS), in directory order.
std::vector<MapLumps> findMaps(const WadFile& wad);

}  // namespace penumbra::wad
