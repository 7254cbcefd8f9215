#include "bvh/morton_build.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <utility>

#include "core/error.h"

namespace penumbra::bvh {
namespace {

// The 10 low bits of v spread to every third bit.
std::uint32_t spreadBits(std::uint32_t v) {
    v &= 0x3ffu;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

std::uint32_t codeOf(std::uint64_t key) { return std::uint32_t(key >> 32); }
std::uint32_t indexOf(std::uint64_t key) { return std::uint32_t(key); }

// Sorts keys by their code (the high 32 bits; 30 used): three 10-bit counting passes, their
// histograms counted in one read. Stable, so equal codes keep index order.
void radixSort(std::vector<std::uint64_t>& keys, std::vector<std::uint64_t>& tmp) {
    constexpr int kPasses = 3, kBits = 10;
    constexpr std::uint32_t kMask = (1u << kBits) - 1;
    std::array<std::array<std::uint32_t, kMask + 1>, kPasses> start{};
    for (std::uint64_t k : keys)
        for (int p = 0; p < kPasses; ++p) ++start[p][(codeOf(k) >> (p * kBits)) & kMask];
    tmp.resize(keys.size());
    for (int p = 0; p < kPasses; ++p) {
        std::uint32_t sum = 0;
        for (std::uint32_t& s : start[p]) sum += std::exchange(s, sum);
        for (std::uint64_t k : keys) tmp[start[p][(codeOf(k) >> (p * kBits)) & kMask]++] = k;
        keys.swap(tmp);
    }
}

// The sanitized boxes, their centres' bounds, then each primitive's key.
void computeKeys(std::span<const Aabb> primBounds, MortonScratch& scratch) {
    const std::size_t n = primBounds.size();
    scratch.boxes.resize(n);
    Vec3 lo{std::numeric_limits<float>::infinity()}, hi{-std::numeric_limits<float>::infinity()};
    for (std::size_t i = 0; i < n; ++i) {
        const Aabb s = sanitizedBounds(primBounds[i]);
        scratch.boxes[i] = s;
        const Vec3 c = (s.lo + s.hi) * 0.5f;
        lo = min(lo, c);
        hi = max(hi, c);
    }
    // Cubic cells (one scale for the three axes): a thin scene's short axis gets fewer distinct
    // codes, so the splits follow its long axes, as SAH would (per-axis scales cost 1.7x in SAH
    // cost on the benchmark's flat field of instances).
    const float size = maxComponent(hi - lo);
    const float scale = size > 0 ? 1024.0f / size : 0.0f;
    auto cell = [scale](float offset) { return std::uint32_t(std::clamp(offset * scale, 0.0f, 1023.0f)); };
    scratch.keys.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Aabb& s = scratch.boxes[i];
        const Vec3 c = (s.lo + s.hi) * 0.5f - lo;
        const std::uint32_t code = (spreadBits(cell(c.x)) << 2) | (spreadBits(cell(c.y)) << 1) | spreadBits(cell(c.z));
        scratch.keys[i] = (std::uint64_t(code) << 32) | std::uint64_t(i);
    }
}

struct Builder {
    const std::vector<Aabb>& boxes;          // sanitized, original order
    const std::vector<std::uint64_t>& keys;  // sorted
    shader::BvhNode* nodes;                  // room for 2n - 1 nodes
    std::uint32_t base;                      // the index of nodes[0] in the output array
    std::uint32_t used = 0;
    bool leafHoldsPrimitive;  // leaf firstOrRight: the primitive's index (else its sorted position)

    // Where [first, last) splits: after the last code that has the range's highest differing
    // bit clear; the middle when all codes are equal or the tree must not grow deeper.
    std::size_t split(std::size_t first, std::size_t last, int depth) const {
        const std::uint32_t a = codeOf(keys[first]), b = codeOf(keys[last - 1]);
        const int levelsNeeded = std::bit_width(last - first);  // for median splits from here
        if (a == b || depth + levelsNeeded >= PN_BVH_MAX_DEPTH) return first + (last - first) / 2;
        const std::uint32_t bit = std::uint32_t(1) << (31 - std::countl_zero(a ^ b));
        // The first code in the range with `bit` set (codes are sorted and agree above it).
        const auto it = std::partition_point(keys.begin() + std::ptrdiff_t(first), keys.begin() + std::ptrdiff_t(last),
                                             [&](std::uint64_t k) { return (codeOf(k) & bit) == 0; });
        return std::size_t(it - keys.begin());
    }

    std::uint32_t leaf(std::size_t position) {
        const std::uint32_t slot = used++;
        const std::uint32_t prim = indexOf(keys[position]);
        const Aabb& box = boxes[prim];
        nodes[slot] = {box.lo, leafHoldsPrimitive ? prim : static_cast<std::uint32_t>(position), box.hi, 1u};
        return slot;
    }

    // Emits the subtree over sorted range [first, last) depth-first; returns its node's slot.
    // Half the nodes are leaves: they are written here without a call of their own.
    std::uint32_t emit(std::size_t first, std::size_t last, int depth) {
        if (last - first == 1) return leaf(first);
        const std::uint32_t slot = used++;
        shader::BvhNode& node = nodes[slot];
        const std::size_t mid = split(first, last, depth);
        const std::uint32_t left = mid - first == 1 ? leaf(first) : emit(first, mid, depth + 1);
        const std::uint32_t right = last - mid == 1 ? leaf(mid) : emit(mid, last, depth + 1);
        const shader::BvhNode &l = nodes[left], &r = nodes[right];
        node = {min(l.boundsMin, r.boundsMin), base + right, max(l.boundsMax, r.boundsMax), 0u};
        return slot;
    }

};

void buildInto(std::span<const Aabb> primBounds, std::vector<shader::BvhNode>& nodes, MortonScratch& scratch,
               bool leafHoldsPrimitive) {
    const std::size_t n = primBounds.size();
    if (n == 0) return;
    computeKeys(primBounds, scratch);
    radixSort(scratch.keys, scratch.keysTmp);
    const std::size_t base = nodes.size();
    nodes.resize(base + 2 * n - 1);
    Builder builder{scratch.boxes, scratch.keys, nodes.data() + base, static_cast<std::uint32_t>(base), 0,
                    leafHoldsPrimitive};
    builder.emit(0, n, 1);
    PN_CHECK(builder.used == 2 * n - 1);
}

}  // namespace

Bvh buildMorton(std::span<const Aabb> primBounds) {
    Bvh bvh;
    MortonScratch scratch;
    buildInto(primBounds, bvh.nodes, scratch, false);
    bvh.primOrder.reserve(scratch.keys.size());
    for (std::uint64_t k : scratch.keys) bvh.primOrder.push_back(indexOf(k));
    return bvh;
}

void appendMorton(std::span<const Aabb> primBounds, std::vector<shader::BvhNode>& nodes, MortonScratch& scratch) {
    buildInto(primBounds, nodes, scratch, true);
}

}  // namespace penumbra::bvh
