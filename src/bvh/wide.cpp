#include "bvh/wide.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"

namespace penumbra::bvh {
namespace {

// What one slot of a wide node will hold: a binary interior node (a wide child), or up to three
// consecutive primitives (in the binary leaf order) of a binary subtree.
struct Entry {
    std::uint32_t binary = 0;  // the binary node it came from
    Aabb box;
    bool interior = false;
    std::uint32_t first = 0,
                  count = 0;  // leaf entries: primitives [first, first + count), old order
};

// A wide node's entries: at most eight, kept off the heap.
struct Entries {
    std::array<Entry, kWideArity> items;
    std::size_t count = 0;
    void push_back(const Entry& e) {
        PN_CHECK(count < items.size());
        items[count++] = e;
    }
    std::size_t size() const { return count; }
    const Entry& operator[](std::size_t i) const { return items[i]; }
    const Entry* begin() const { return items.data(); }
    const Entry* end() const { return items.data() + count; }
};
using SlotOf = std::array<int, kWideArity>;  // the slot of each entry

// The primitives of a small subtree (a slot's leaf): its first (leaf order) and count.
struct Range {
    std::uint32_t first = 0, count = 0;
};
Range subtreeRange(const std::vector<shader::BvhNode>& nodes, std::uint32_t n) {
    if (nodes[n].triCount > 0) return {nodes[n].firstOrRight, nodes[n].triCount};
    const Range left = subtreeRange(nodes, n + 1),
                right = subtreeRange(nodes, nodes[n].firstOrRight);
    return {left.first, left.count + right.count};
}

Aabb boxOf(const shader::BvhNode& n) { return Aabb{n.boundsMin, n.boundsMax}; }

// Which binary subtrees become a wide node's slots, chosen by the SAH dynamic program of
// Ylitie et al. (section 3.1): cost[n][i] is the least SAH cost of subtree n spread over at most
// i + 1 slots of its wide parent, as a leaf (at most three primitives per slot), as one wide
// interior child, or split between its two children. Binary leaves of more than three
// primitives take several slots (or become a wide node of their pieces).
// (The binary builder bounds the depth by PN_BVH_MAX_DEPTH, which bounds the recursion.)
class Collapser {
public:
    explicit Collapser(const std::vector<shader::BvhNode>& nodes)
        : nodes_(nodes), choice_(nodes.size()), split_(nodes.size()), rootCount_(solve(0).count) {}

    // The wide node made from binary node b (the root, or an interior slot's subtree).
    Entries entries(std::uint32_t b) const {
        Entries out;
        if (nodes_[b].triCount > 0 ||
            (b == 0 && rootCount_ <= std::uint32_t(kWideLeafPrimitives))) {
            addLeaf(b, out);
        } else {
            const int k = split_[b];
            expand(b + 1, k, out);
            expand(nodes_[b].firstOrRight, kWideArity - k, out);
        }
        return out;
    }

private:
    static constexpr float kNodeCost = 1.0f;       // visiting a wide node
    static constexpr float kPrimitiveCost = 0.3f;  // one primitive test (the paper's ratio)
    static constexpr std::uint8_t kLeaf = 0, kInterior = 1;  // choices; 2 + k: split, k slots left

    float area(std::uint32_t n) const { return std::max(boxOf(nodes_[n]).halfArea(), 0.0f); }
    struct Costs {
        std::array<float, kWideArity> cost;
        std::uint32_t count;  // primitives below
    };

    // Post-order, so that only the costs along the current path are alive (the choices are kept
    // for every node); the depth is at most PN_BVH_MAX_DEPTH.
    Costs solve(std::uint32_t n) {
        const shader::BvhNode& node = nodes_[n];
        PN_CHECK(node.triCount > 0 ||
                 (node.firstOrRight > n + 1 && node.firstOrRight < nodes_.size()));
        if (node.triCount > std::uint32_t(kWideMaxBinaryLeaf))
            throw Error("the wide BVH takes binary leaves of at most " +
                        std::to_string(kWideMaxBinaryLeaf) + " primitives, not " +
                        std::to_string(node.triCount));
        float splitCost[kWideArity] = {};  // [i]: the children sharing i + 1 slots
        int bestSplit[kWideArity] = {};
        std::uint32_t count = node.triCount;
        if (node.triCount == 0) {
            const Costs l = solve(n + 1), r = solve(node.firstOrRight);
            const auto& left = l.cost;
            const auto& right = r.cost;
            count = l.count + r.count;
            for (int i = 1; i < kWideArity; ++i) {
                splitCost[i] = std::numeric_limits<float>::infinity();
                for (int k = 1; k <= i; ++k) {
                    const float c = left[k - 1] + right[i - k];
                    if (c < splitCost[i]) {
                        splitCost[i] = c;
                        bestSplit[i] = k;
                    }
                }
            }
        }
        const float leafCost = area(n) * kPrimitiveCost * float(count);
        const bool canBeLeaf = node.triCount > 0 || count <= std::uint32_t(kWideLeafPrimitives);
        const int leafSlots = int((count + 2) / 3);
        // As a wide node of its own: its leaf pieces, or its children over eight slots.
        const float interiorCost =
            area(n) * kNodeCost + (node.triCount > 0 ? leafCost : splitCost[kWideArity - 1]);
        split_[n] = std::uint8_t(bestSplit[kWideArity - 1]);
        std::array<float, kWideArity> cost;
        for (int i = 0; i < kWideArity; ++i) {
            float best = interiorCost;
            std::uint8_t choice = kInterior;
            if (canBeLeaf && leafSlots <= i + 1 && leafCost <= best) {
                best = leafCost;
                choice = kLeaf;
            }
            if (node.triCount == 0 && i > 0 && splitCost[i] < best) {
                best = splitCost[i];
                choice = std::uint8_t(2 + bestSplit[i]);
            }
            if (i > 0 && cost[i - 1] <= best) {  // fewer slots do at least as well
                best = cost[i - 1];
                choice = choice_[n][i - 1];
            }
            cost[i] = best;
            choice_[n][i] = choice;
        }
        return {cost, count};
    }

    // Subtree n's entries in at most `slots` slots, as the program chose.
    void expand(std::uint32_t n, int slots, Entries& out) const {
        const std::uint8_t choice = choice_[n][slots - 1];
        if (choice == kLeaf) {
            addLeaf(n, out);
        } else if (choice == kInterior) {
            out.push_back({n, boxOf(nodes_[n]), true, 0, 0});
        } else {
            const int k = choice - 2;
            expand(n + 1, k, out);
            expand(nodes_[n].firstOrRight, slots - k, out);
        }
    }

    void addLeaf(std::uint32_t n, Entries& out) const {
        const Range range = subtreeRange(nodes_, n);  // a binary leaf, or at most three primitives
        for (std::uint32_t k = 0; k < range.count; k += kWideLeafPrimitives)
            out.push_back({n, boxOf(nodes_[n]), false, range.first + k,
                           std::min<std::uint32_t>(kWideLeafPrimitives, range.count - k)});
    }

    const std::vector<shader::BvhNode>& nodes_;
    std::vector<std::array<std::uint8_t, kWideArity>> choice_;
    std::vector<std::uint8_t> split_;  // the best split of a node's children over eight slots
    std::uint32_t rootCount_;
};

// Slot of each entry: slot s goes to the entry nearest a ray travelling along the diagonal with
// sign bits s (bit k set: negative along axis k), greedily by the smallest projection of the
// entry's centre (relative to the node's) on that diagonal.
SlotOf assignSlots(const Entries& entries, const Aabb& parent) {
    const Vec3 centre = parent.center();
    float cost[kWideArity][kWideArity];
    for (std::size_t e = 0; e < entries.size(); ++e) {
        const Vec3 offset = entries[e].box.center() - centre;
        for (int s = 0; s < kWideArity; ++s)
            cost[e][s] = (s & 1 ? -offset.x : offset.x) + (s & 2 ? -offset.y : offset.y) +
                         (s & 4 ? -offset.z : offset.z);
    }
    SlotOf slotOf;
    slotOf.fill(-1);
    bool slotTaken[kWideArity] = {};
    for (std::size_t round = 0; round < entries.size(); ++round) {
        float best = std::numeric_limits<float>::infinity();
        std::size_t bestEntry = 0;
        int bestSlot = -1;
        for (std::size_t e = 0; e < entries.size(); ++e) {
            if (slotOf[e] >= 0) continue;
            for (int s = 0; s < kWideArity; ++s) {
                if (slotTaken[s] || (bestSlot >= 0 && !(cost[e][s] < best))) continue;
                best = cost[e][s];
                bestEntry = e;
                bestSlot = s;
            }
        }
        slotOf[bestEntry] = bestSlot;
        slotTaken[bestSlot] = true;
    }
    return slotOf;
}

void setByte(std::uint32_t (&words)[2], int slot, std::uint32_t value) {
    const int shift = 8 * (slot % 4);
    words[slot / 4] = (words[slot / 4] & ~(0xffu << shift)) | (value << shift);
}
std::uint32_t getByte(const std::uint32_t (&words)[2], int slot) {
    return (words[slot / 4] >> (8 * (slot % 4))) & 0xffu;
}

float exponentScale(std::uint32_t biased) { return std::bit_cast<float>(biased << 23); }

// A plane decoded as the shader decodes it: origin + q * 2^e (the product is exact).
float decodePlane(float origin, std::uint32_t q, float scale) { return origin + float(q) * scale; }

// Quantizes the entries' boxes along one axis: the smallest exponent whose 255 steps cover the
// node, with each lower plane rounded down and each upper plane up until the decoded planes
// contain the child's (checked in float, as decoded). Returns the biased exponent.
std::uint32_t quantizeAxis(const Entries& entries, const SlotOf& slotOf, int axis, float origin,
                           float top, std::uint32_t (&lo)[2], std::uint32_t (&hi)[2]) {
    const double extent = double(top) - double(origin);
    int e = -126;
    if (extent > 0) e = std::clamp(int(std::ceil(std::log2(extent / 255.0))), -126, 127);
    for (;; ++e) {
        PN_CHECK(e <= 127);
        const std::uint32_t biased = std::uint32_t(e + 127);
        const float scale = exponentScale(biased);
        bool fits = true;
        for (std::size_t k = 0; k < entries.size() && fits; ++k) {
            const float cLo = entries[k].box.lo[axis], cHi = entries[k].box.hi[axis];
            double qLo = std::floor((double(cLo) - double(origin)) / double(scale));
            double qHi = std::ceil((double(cHi) - double(origin)) / double(scale));
            std::uint32_t l = std::uint32_t(std::clamp(qLo, 0.0, 255.0));
            std::uint32_t h = std::uint32_t(std::clamp(qHi, 0.0, 255.0));
            while (l > 0 && decodePlane(origin, l, scale) > cLo) --l;
            while (h < 255 && decodePlane(origin, h, scale) < cHi) ++h;
            if (decodePlane(origin, l, scale) > cLo || decodePlane(origin, h, scale) < cHi) {
                fits = false;
                break;
            }
            setByte(lo, slotOf[k], l);
            setByte(hi, slotOf[k], h);
        }
        if (fits) return biased;
    }
}

shader::WideNode encodeNode(const Entries& entries, const SlotOf& slotOf) {
    Aabb box;
    for (const Entry& e : entries) box.grow(e.box);
    shader::WideNode node{};
    node.origin = box.lo;
    std::uint32_t exponents = 0;
    exponents |= quantizeAxis(entries, slotOf, 0, box.lo.x, box.hi.x, node.loX, node.hiX);
    exponents |= quantizeAxis(entries, slotOf, 1, box.lo.y, box.hi.y, node.loY, node.hiY) << 8;
    exponents |= quantizeAxis(entries, slotOf, 2, box.lo.z, box.hi.z, node.loZ, node.hiZ) << 16;
    node.exponentsMask = exponents;
    return node;
}

std::uint32_t unaryCount(std::uint32_t count) { return (1u << count) - 1u; }

}  // namespace

std::uint32_t wideMeta(const shader::WideNode& node, int slot) { return getByte(node.meta, slot); }

Aabb wideSlotBounds(const shader::WideNode& node, int slot) {
    if (wideSlotEmpty(wideMeta(node, slot))) return Aabb{};
    const float sx = exponentScale(node.exponentsMask & 0xffu);
    const float sy = exponentScale((node.exponentsMask >> 8) & 0xffu);
    const float sz = exponentScale((node.exponentsMask >> 16) & 0xffu);
    Aabb b;
    b.lo = Vec3{decodePlane(node.origin.x, getByte(node.loX, slot), sx),
                decodePlane(node.origin.y, getByte(node.loY, slot), sy),
                decodePlane(node.origin.z, getByte(node.loZ, slot), sz)};
    b.hi = Vec3{decodePlane(node.origin.x, getByte(node.hiX, slot), sx),
                decodePlane(node.origin.y, getByte(node.hiY, slot), sy),
                decodePlane(node.origin.z, getByte(node.hiZ, slot), sz)};
    return b;
}

std::uint32_t wideChildIndex(const shader::WideNode& node, int slot) {
    const std::uint32_t interior = node.exponentsMask >> 24;
    return node.childBase + std::uint32_t(std::popcount(interior & ((1u << slot) - 1u)));
}

WideBvh collapseToWide(Bvh& bvh) {
    WideBvh out;
    if (bvh.nodes.empty()) return out;
    const Collapser collapser(bvh.nodes);
    std::vector<std::uint32_t>
        newOrder;  // newOrder[k] = old leaf-order position of the k-th primitive
    newOrder.reserve(bvh.primOrder.size());
    struct Pending {
        std::uint32_t wide, binary, depth;
    };
    std::vector<Pending> pending = {{0, 0, 1}};
    out.nodes.reserve(bvh.nodes.size() / 6 + 1);  // about one wide node per eight binary ones
    out.nodes.emplace_back();
    while (!pending.empty()) {
        const Pending p = pending.back();
        pending.pop_back();
        out.maxDepth = std::max(out.maxDepth, p.depth);
        const Entries entries = collapser.entries(p.binary);
        const SlotOf slotOf = assignSlots(entries, boxOf(bvh.nodes[p.binary]));
        shader::WideNode node = encodeNode(entries, slotOf);
        // Leaves' primitives in entry order (the pieces of one binary leaf stay together), then
        // the interior children in slot order, contiguous.
        node.primBase = std::uint32_t(newOrder.size());
        for (std::size_t k = 0; k < entries.size(); ++k) {
            if (entries[k].interior) continue;
            const std::uint32_t offset = std::uint32_t(newOrder.size()) - node.primBase;
            PN_CHECK(offset + entries[k].count <= std::uint32_t(kWideArity * kWideLeafPrimitives));
            setByte(node.meta, slotOf[k], (unaryCount(entries[k].count) << 5) | offset);
            for (std::uint32_t j = 0; j < entries[k].count; ++j)
                newOrder.push_back(entries[k].first + j);
        }
        node.childBase = std::uint32_t(out.nodes.size());
        std::uint32_t interiorMask = 0;
        for (int s = 0; s < kWideArity; ++s) {
            for (std::size_t k = 0; k < entries.size(); ++k) {
                if (slotOf[k] != s || !entries[k].interior) continue;
                interiorMask |= 1u << s;
                setByte(node.meta, s, 0x38u | std::uint32_t(s));
                pending.push_back(
                    {std::uint32_t(out.nodes.size()), entries[k].binary, p.depth + 1});
                out.nodes.emplace_back();
            }
        }
        node.exponentsMask |= interiorMask << 24;
        out.nodes[p.wide] = node;
    }
    PN_CHECK(newOrder.size() == bvh.primOrder.size());

    // The binary tree in the new order: each binary leaf's primitives stayed consecutive.
    std::vector<std::uint32_t> newPosition(newOrder.size());
    for (std::uint32_t k = 0; k < newOrder.size(); ++k) newPosition[newOrder[k]] = k;
    for (shader::BvhNode& n : bvh.nodes) {
        if (n.triCount == 0) continue;
        const std::uint32_t first = newPosition[n.firstOrRight];
        for (std::uint32_t j = 1; j < n.triCount; ++j)
            PN_CHECK(newPosition[n.firstOrRight + j] == first + j);
        n.firstOrRight = first;
    }
    std::vector<std::uint32_t> primOrder(newOrder.size());
    for (std::size_t k = 0; k < newOrder.size(); ++k) primOrder[k] = bvh.primOrder[newOrder[k]];
    bvh.primOrder = std::move(primOrder);
    return out;
}

}  // namespace penumbra::bvh
