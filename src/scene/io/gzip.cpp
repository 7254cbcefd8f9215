#include "scene/io/gzip.h"

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <limits>

#include "core/big_buffer.h"
#include "core/error.h"

namespace penumbra {

bool isGzip(std::string_view bytes) {
    return bytes.size() >= 2 && std::uint8_t(bytes[0]) == 0x1f && std::uint8_t(bytes[1]) == 0x8b;
}

namespace {

// zlib's stream, released on every path out.
struct Inflater {
    z_stream z{};
    Inflater() {
        // 15 + 16: a gzip wrapper, with the largest window.
        if (inflateInit2(&z, 15 + 16) != Z_OK) throw Error("cannot start zlib");
    }
    ~Inflater() { inflateEnd(&z); }
    Inflater(const Inflater&) = delete;
    Inflater& operator=(const Inflater&) = delete;
};

// Deflate never expands more than about 1032 to 1, so no real stream inflates beyond this.
constexpr std::size_t kMaxRatio = 1032;

// The last member's ISIZE (uncompressed size mod 2^32): a first guess at the output size only,
// and one the file itself states, so it is believed only as far as deflate's ratio allows.
std::size_t sizeHint(std::string_view bytes, std::size_t maxBytes) {
    if (bytes.size() < 18) return 0;
    const auto* p = reinterpret_cast<const std::uint8_t*>(bytes.data() + bytes.size() - 4);
    const std::size_t isize = std::size_t(p[0]) | std::size_t(p[1]) << 8 | std::size_t(p[2]) << 16 |
                              std::size_t(p[3]) << 24;
    return std::min({isize, maxBytes, bytes.size() * kMaxRatio});
}

}  // namespace

std::string gunzip(std::string_view bytes, std::size_t maxBytes, const std::string& name) {
    if (!isGzip(bytes)) throw Error(name + ": not a gzip file");
    Inflater inf;
    std::string out;
    std::size_t capacity = std::max<std::size_t>(sizeHint(bytes, maxBytes), 1 << 16);
    out.reserve(capacity + 1);
    adviseHugePages(out.data(), capacity);
    out.resize(capacity);
    std::size_t produced = 0;
    inf.z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    std::size_t inputLeft = bytes.size();
    for (;;) {
        if (produced == out.size()) {
            if (out.size() >= maxBytes)
                throw Error(name + ": inflates to more than " + std::to_string(maxBytes >> 20) +
                            " MiB, the limit for compressed scene files");
            out.resize(std::min(maxBytes, out.size() * 2));
        }
        // zlib counts in 32-bit units: feed and drain at most 1 GiB per call.
        const uInt in = uInt(std::min<std::size_t>(inputLeft, std::size_t(1) << 30));
        const uInt room = uInt(std::min<std::size_t>(out.size() - produced, std::size_t(1) << 30));
        inf.z.avail_in = in;
        inf.z.next_out = reinterpret_cast<Bytef*>(out.data() + produced);
        inf.z.avail_out = room;
        const int rc = inflate(&inf.z, Z_NO_FLUSH);
        inputLeft -= in - inf.z.avail_in;
        produced += room - inf.z.avail_out;
        if (rc == Z_STREAM_END) {
            // Another member may follow (concatenated .gz files); trailing zeros are padding.
            const auto* rest = reinterpret_cast<const char*>(inf.z.next_in);
            if (inputLeft == 0 ||
                std::all_of(rest, rest + inputLeft, [](char c) { return c == 0; }))
                break;
            if (inflateReset(&inf.z) != Z_OK) throw Error(name + ": corrupt gzip data");
            continue;
        }
        if (rc == Z_BUF_ERROR && inputLeft == 0 && inf.z.avail_out > 0)
            throw Error(name + ": the gzip data is truncated");
        if (rc != Z_OK && rc != Z_BUF_ERROR)
            throw Error(name + ": corrupt gzip data (" +
                        (inf.z.msg ? inf.z.msg : "zlib error " + std::to_string(rc)) + ")");
    }
    out.resize(produced);
    return out;
}

}  // namespace penumbra
