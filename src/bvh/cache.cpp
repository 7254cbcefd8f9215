#include "bvh/cache.h"

#include <xxhash.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include "bvh/validate.h"
#include "core/atomic_file.h"
#include "core/big_buffer.h"
#include "core/error.h"
#include "core/log.h"

namespace penumbra::bvh {
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'P', 'N', 'B', 'V', 'H', 'C', '0', '1'};

// 64 bytes at the start of every entry; numbers in the host's byte order (a cache is local).
struct FileHeader {
    char magic[8];
    std::uint32_t builderVersion;
    std::uint32_t nodeBytes;  // sizeof(shader::BvhNode)
    std::uint64_t keyLow, keyHigh;
    std::uint64_t nodeCount;
    std::uint64_t primCount;
    std::uint64_t payloadHash;  // XXH3-64 of the nodes and primOrder that follow
    std::uint64_t reserved;
};
static_assert(sizeof(FileHeader) == 64);

CacheSettings& settingsStore() {
    static CacheSettings settings;
    return settings;
}

XXH128_hash_t keyOf(std::span<const Triangle> tris, std::span<const Aabb> extra,
                    const BuildOptions& o) {
    XXH3_state_t* state = XXH3_createState();
    if (!state) throw std::bad_alloc();
    XXH3_128bits_reset(state);
    const std::uint64_t fields[] = {kBuilderVersion,
                                    sizeof(shader::BvhNode),
                                    PN_BVH_MAX_DEPTH,
                                    std::uint64_t(std::uint32_t(o.bins)),
                                    std::uint64_t(std::uint32_t(o.maxLeafSize)),
                                    std::bit_cast<std::uint32_t>(o.traversalCost),
                                    std::bit_cast<std::uint32_t>(o.intersectCost),
                                    tris.size(),
                                    extra.size()};
    XXH3_128bits_update(state, fields, sizeof fields);
    XXH3_128bits_update(state, tris.data(), tris.size_bytes());
    XXH3_128bits_update(state, extra.data(), extra.size_bytes());
    const XXH128_hash_t key = XXH3_128bits_digest(state);
    XXH3_freeState(state);
    return key;
}

fs::path entryPath(const fs::path& dir, XXH128_hash_t key) {
    char name[48];
    std::snprintf(name, sizeof name, "bvh-%016llx%016llx.bin",
                  static_cast<unsigned long long>(key.high64),
                  static_cast<unsigned long long>(key.low64));
    return dir / name;
}

std::uint64_t payloadHash(const Bvh& bvh) {
    XXH3_state_t* state = XXH3_createState();
    if (!state) throw std::bad_alloc();
    XXH3_64bits_reset(state);
    XXH3_64bits_update(state, bvh.nodes.data(), bvh.nodes.size() * sizeof(shader::BvhNode));
    XXH3_64bits_update(state, bvh.primOrder.data(), bvh.primOrder.size() * sizeof(std::uint32_t));
    const std::uint64_t h = XXH3_64bits_digest(state);
    XXH3_freeState(state);
    return h;
}

std::vector<Aabb> allBounds(std::span<const Triangle> tris, std::span<const Aabb> extra) {
    std::vector<Aabb> boxes;
    reserveHuge(boxes, tris.size() + extra.size());
    for (const Triangle& t : tris) boxes.push_back(bounds(t));
    boxes.insert(boxes.end(), extra.begin(), extra.end());
    return boxes;
}

Bvh buildDirect(std::span<const Triangle> tris, std::span<const Aabb> extra,
                const BuildOptions& options) {
    if (extra.empty()) return buildTriangles(tris, options);
    return build(allBounds(tris, extra), options);
}

// The entry at `path`, or why it cannot be used. Nothing in the file is trusted: sizes are
// checked against the file's length and the expected counts before anything is allocated,
// the payload against its hash, and the tree against the geometry (validate()).
bool readEntry(const fs::path& path, XXH128_hash_t key, std::size_t primCount,
               std::span<const Triangle> tris, std::span<const Aabb> extra, Bvh& out,
               std::string& why) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        why = "cannot be opened";
        return false;
    }
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(path, ec);
    FileHeader h{};
    if (ec || size < sizeof h || !in.read(reinterpret_cast<char*>(&h), sizeof h)) {
        why = "is truncated";
        return false;
    }
    if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0 || h.builderVersion != kBuilderVersion ||
        h.nodeBytes != sizeof(shader::BvhNode) || h.keyLow != key.low64 ||
        h.keyHigh != key.high64) {
        why = "is not an entry for this geometry and builder";
        return false;
    }
    if (h.primCount != primCount || h.nodeCount == 0 ||
        h.nodeCount > 2 * std::uint64_t(primCount) ||
        size != sizeof h + h.nodeCount * sizeof(shader::BvhNode) +
                    h.primCount * sizeof(std::uint32_t)) {
        why = "has sizes that do not match";
        return false;
    }
    reserveHuge(out.nodes, std::size_t(h.nodeCount));
    out.nodes.resize(std::size_t(h.nodeCount));
    out.primOrder.resize(std::size_t(h.primCount));
    if (!in.read(reinterpret_cast<char*>(out.nodes.data()),
                 std::streamsize(h.nodeCount * sizeof(shader::BvhNode))) ||
        !in.read(reinterpret_cast<char*>(out.primOrder.data()),
                 std::streamsize(h.primCount * sizeof(std::uint32_t)))) {
        why = "is truncated";
        return false;
    }
    if (payloadHash(out) != h.payloadHash) {
        why = "is damaged (checksum mismatch)";
        return false;
    }
    try {
        validate(out, allBounds(tris, extra));
    } catch (const Error& e) {
        why = std::string("holds an invalid tree (") + e.what() + ")";
        return false;
    }
    return true;
}

void writeEntry(const fs::path& path, XXH128_hash_t key, const Bvh& bvh) {
    FileHeader h{};
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.builderVersion = kBuilderVersion;
    h.nodeBytes = sizeof(shader::BvhNode);
    h.keyLow = key.low64;
    h.keyHigh = key.high64;
    h.nodeCount = bvh.nodes.size();
    h.primCount = bvh.primOrder.size();
    h.payloadHash = payloadHash(bvh);
    writeFileAtomically(path, [&](const fs::path& tmp) {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(&h), sizeof h);
        out.write(reinterpret_cast<const char*>(bvh.nodes.data()),
                  std::streamsize(bvh.nodes.size() * sizeof(shader::BvhNode)));
        out.write(reinterpret_cast<const char*>(bvh.primOrder.data()),
                  std::streamsize(bvh.primOrder.size() * sizeof(std::uint32_t)));
        out.flush();
        if (!out) throw Error("cannot write '" + tmp.string() + "'");
    });
}

// Deletes the least recently used entries (and temporaries left by crashed writers) until the
// cache fits in maxBytes.
void prune(const fs::path& dir, std::uint64_t maxBytes, const fs::path& keep) {
    struct Entry {
        fs::path path;
        fs::file_time_type time;
        std::uintmax_t size;
    };
    std::vector<Entry> entries;
    std::uint64_t total = 0;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
        const std::string name = e.path().filename().string();
        if (name.rfind("bvh-", 0) != 0 || !e.is_regular_file(ec)) continue;
        const std::uintmax_t size = e.file_size(ec);
        if (ec) continue;
        const auto time = e.last_write_time(ec);
        if (ec) continue;
        entries.push_back({e.path(), time, size});
        total += size;
    }
    if (total <= maxBytes) return;
    std::sort(entries.begin(), entries.end(),
              [](const Entry& a, const Entry& b) { return a.time < b.time; });
    for (const Entry& e : entries) {
        if (total <= maxBytes) break;
        if (e.path == keep) continue;
        if (fs::remove(e.path, ec)) total -= e.size;
    }
}

}  // namespace

void setCacheSettings(const CacheSettings& settings) { settingsStore() = settings; }
const CacheSettings& cacheSettings() { return settingsStore(); }

CachedBuild buildCached(std::span<const Triangle> tris, std::span<const Aabb> extra,
                        const BuildOptions& options, const CacheSettings& settings) {
    CachedBuild result;
    const std::size_t primCount = tris.size() + extra.size();
    if (!settings.enabled || settings.directory.empty() ||
        primCount < std::max<std::size_t>(settings.minPrimitives, 1)) {
        result.bvh = buildDirect(tris, extra, options);
        return result;
    }
    const XXH128_hash_t key = keyOf(tris, extra, options);
    const fs::path path = entryPath(settings.directory, key);
    std::error_code ec;
    if (fs::exists(path, ec)) {
        std::string why;
        if (readEntry(path, key, primCount, tris, extra, result.bvh, why)) {
            fs::last_write_time(path, fs::file_time_type::clock::now(), ec);  // recently used
            result.fromCache = true;
            return result;
        }
        logWarning("BVH cache entry '" + path.string() + "' " + why + "; rebuilding it");
        result.bvh = Bvh{};
    }
    result.bvh = buildDirect(tris, extra, options);
    try {
        fs::create_directories(settings.directory, ec);
        writeEntry(path, key, result.bvh);
        prune(settings.directory, settings.maxBytes, path);
    } catch (const Error& e) {
        logWarning(std::string("cannot store the BVH in the cache (") + e.what() +
                   "); set PENUMBRA_CACHE_DIR to a writable folder or pass --no-bvh-cache");
    }
    return result;
}

}  // namespace penumbra::bvh
