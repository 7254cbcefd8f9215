// The compressed 8-wide BVH (shader::WideNode, the CWBVH layout of Ylitie, Karras and Laine 2017),
// made by collapsing the binary SAH tree: each wide node takes the binary subtree below it and
// opens its largest interior boxes until eight slots are used. The GPU walks it with
// shaders/lib/wide_bvh.glsl; traverse_wide_cpu.h is the reference walk the tests compare it with.
#pragma once

#include <cstdint>
#include <vector>

#include "bvh/builder.h"
#include "core/aabb.h"
#include "shared/types.h"

namespace penumbra::bvh {

inline constexpr int kWideArity = 8;
inline constexpr int kWideLeafPrimitives =
    3;  // a slot's leaf holds at most this many (unary count in 3 bits)
// A binary leaf of more than kWideLeafPrimitives spreads over several slots, at most the eight of
// a wide node of its own.
inline constexpr int kWideMaxBinaryLeaf = kWideArity * kWideLeafPrimitives;

struct WideBvh {
    std::vector<shader::WideNode> nodes;  // root first; empty when the binary tree is
    std::uint32_t maxDepth = 0;           // wide levels (root = 1); at most the binary tree's depth
};

struct CollapseOptions {
    // Binary subtrees of at least this many primitives hand the subtrees below them to tasks on
    // every hardware thread; 0 collapses on the calling thread. The result does not depend on it.
    std::uint32_t taskPrimitives = 4096;
};

// Builds the wide tree and reorders the binary tree's primitives (bvh.primOrder and its leaves'
// first indices) so that each wide node's leaf primitives are contiguous from its primBase. The
// binary tree stays valid and shares that primitive order, so both walk the same TriVerts.
// Throws penumbra::Error for binary leaves of more than kWideMaxBinaryLeaf primitives.
WideBvh collapseToWide(Bvh& bvh, const CollapseOptions& options = {});

// Slot i's meta byte (see shader::WideNode) and decoded box, exactly as the traversal computes it.
std::uint32_t wideMeta(const shader::WideNode& node, int slot);
Aabb wideSlotBounds(const shader::WideNode& node, int slot);

inline bool wideSlotEmpty(std::uint32_t meta) { return meta == 0; }
inline bool wideSlotInterior(std::uint32_t meta) { return (meta & 0xf8u) == 0x38u; }
inline std::uint32_t wideLeafCount(std::uint32_t meta) {
    return meta >> 7 ? 3u : (meta >> 6 ? 2u : 1u);
}
inline std::uint32_t wideLeafOffset(std::uint32_t meta) { return meta & 31u; }
// The wide node index of an interior slot: childBase plus the interior slots below it.
std::uint32_t wideChildIndex(const shader::WideNode& node, int slot);

}  // namespace penumbra::bvh
