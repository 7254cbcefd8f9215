// An on-disk cache of built BVHs, so that opening a big model a second time skips the build.
// An entry is keyed by a 128-bit hash (XXH3) of exactly what the builder would be given (every
// triangle's vertices and every extra box, in order) plus the builder's version and options: a
// file whose geometry changed in any bit, a different --map, or a new builder can never meet a
// stale entry. Entries are written atomically, checksummed, validated structurally when read
// (a damaged or foreign file is bad input: it is rebuilt with a warning, never trusted), and the
// oldest are deleted when the cache outgrows its size limit.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>

#include "bvh/builder.h"
#include "bvh/triangle.h"

namespace penumbra::bvh {

// Bump whenever build() can give a different tree for the same input.
inline constexpr std::uint32_t kBuilderVersion = 2;

struct CacheSettings {
    bool enabled = false;
    std::filesystem::path directory;
    std::uint64_t maxBytes = std::uint64_t(2) << 30;  // the oldest entries go beyond this
    std::size_t minPrimitives = 50000;  // smaller scenes build faster than a cache could answer
};

// Process-wide, off until the command line turns it on, so tests and tools never touch the
// disk unless they ask to. Set it before any build starts.
void setCacheSettings(const CacheSettings& settings);
const CacheSettings& cacheSettings();

struct CachedBuild {
    Bvh bvh;
    bool fromCache = false;
};

// The BVH over `tris` followed by `extra` boxes (primitive i >= tris.size() is extra[i - size]),
// as build()/buildTriangles() make it, read from the cache when it holds it and stored there
// when it did not. Cache problems are warnings; the build itself never fails because of them.
CachedBuild buildCached(std::span<const Triangle> tris, std::span<const Aabb> extra,
                        const BuildOptions& options,
                        const CacheSettings& settings = cacheSettings());

}  // namespace penumbra::bvh
