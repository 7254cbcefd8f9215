#include "bvh/morton_build.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>

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

// Sorts (code, index) pairs by code: three 10-bit counting passes.
void radixSort(std::vector<std::uint32_t>& codes, std::vector<std::uint32_t>& order) {
    std::vector<std::uint32_t> codesTmp(codes.size()), orderTmp(order.size());
    for (int shift = 0; shift < 30; shift += 10) {
        std::array<std::uint32_t, 1025> start{};
        for (std::uint32_t c : codes) ++start[((c >> shift) & 0x3ffu) + 1];
        for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
        for (std::size_t i = 0; i < codes.size(); ++i) {
            const std::uint32_t slot = start[(codes[i] >> shift) & 0x3ffu]++;
            codesTmp[slot] = codes[i];
            orderTmp[slot] = order[i];
        }
        codes.swap(codesTmp);
        order.swap(orderTmp);
    }
}

struct Builder {
    std::span<const Aabb> boxes;  // sanitized, original order
    const std::vector<std::uint32_t>& codes;  // sorted
    const std::vector<std::uint32_t>& order;
    std::vector<shader::BvhNode>& nodes;

    // Where [first, last) splits: after the last code that has the range's highest differing
    // bit clear; the middle when all codes are equal or the tree must not grow deeper.
    std::size_t split(std::size_t first, std::size_t last, int depth) const {
        const std::uint32_t a = codes[first], b = codes[last - 1];
        const int levelsNeeded = std::bit_width(last - first);  // for median splits from here
        if (a == b || depth + levelsNeeded >= PN_BVH_MAX_DEPTH) return first + (last - first) / 2;
        const std::uint32_t bit = std::uint32_t(1) << (31 - std::countl_zero(a ^ b));
        // The first code in the range with `bit` set (codes are sorted and agree above it).
        const auto it = std::partition_point(codes.begin() + std::ptrdiff_t(first), codes.begin() + std::ptrdiff_t(last),
                                             [&](std::uint32_t c) { return (c & bit) == 0; });
        return std::size_t(it - codes.begin());
    }

    // Emits the subtree over sorted range [first, last) depth-first; returns its node's index.
    std::uint32_t emit(std::size_t first, std::size_t last, int depth) {
        const auto index = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        if (last - first == 1) {
            const Aabb& box = boxes[order[first]];
            nodes[index] = {box.lo, static_cast<std::uint32_t>(first), box.hi, 1u};
            return index;
        }
        const std::size_t mid = split(first, last, depth);
        const std::uint32_t left = emit(first, mid, depth + 1);
        const std::uint32_t right = emit(mid, last, depth + 1);
        Aabb box;
        for (std::uint32_t child : {left, right}) {
            box.grow(nodes[child].boundsMin);
            box.grow(nodes[child].boundsMax);
        }
        nodes[index] = {box.lo, right, box.hi, 0u};
        return index;
    }
};

}  // namespace

Bvh buildMorton(std::span<const Aabb> primBounds) {
    Bvh bvh;
    const std::size_t n = primBounds.size();
    if (n == 0) return bvh;
    std::vector<Aabb> boxes(n);
    Aabb centres;
    for (std::size_t i = 0; i < n; ++i) {
        boxes[i] = sanitizedBounds(primBounds[i]);
        centres.grow((boxes[i].lo + boxes[i].hi) * 0.5f);
    }
    // Cubic cells (one scale for the three axes): a thin scene's short axis gets fewer distinct
    // codes, so the splits follow its long axes, as SAH would (per-axis scales cost 1.7x in SAH
    // cost on the benchmark's flat field of instances).
    const float size = maxComponent(centres.hi - centres.lo);
    auto cell = [size](float offset) {
        return size > 0 ? std::uint32_t(std::clamp(offset / size * 1024.0f, 0.0f, 1023.0f)) : 0u;
    };
    std::vector<std::uint32_t> codes(n), order(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 c = (boxes[i].lo + boxes[i].hi) * 0.5f - centres.lo;
        codes[i] = (spreadBits(cell(c.x)) << 2) | (spreadBits(cell(c.y)) << 1) | spreadBits(cell(c.z));
        order[i] = static_cast<std::uint32_t>(i);
    }
    radixSort(codes, order);
    bvh.nodes.reserve(2 * n - 1);
    Builder{boxes, codes, order, bvh.nodes}.emit(0, n, 1);
    bvh.primOrder = std::move(order);
    return bvh;
}

}  // namespace penumbra::bvh
