#include "bvh/wide.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include "core/big_buffer.h"
#include "core/error.h"
#include "core/parallel.h"

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
// With taskPrimitives > 0, subtrees of fewer primitives below larger ones are solved and counted
// as tasks on every hardware thread; each node's results are the same either way.
class Collapser {
public:
    Collapser(const std::vector<shader::BvhNode>& nodes, std::uint32_t taskPrimitives)
        : nodes_(nodes),
          choice_(nodes.size()),
          split_(nodes.size()),
          count_(nodes.size()),
          wideCount_(nodes.size()),
          taskPrimitives_(taskPrimitives) {
        rootCount_ = solveAll();
        countAll();
    }

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
    std::uint32_t primitives(std::uint32_t b) const { return count_[b]; }  // below binary node b
    // Wide nodes in the wide subtree headed by binary node b (b's own included).
    std::uint32_t wideNodes(std::uint32_t b) const { return wideCount_[b]; }
    // Whether the wide node headed by b hands its children to tasks.
    bool large(std::uint32_t b) const { return taskPrimitives_ > 0 && count_[b] >= taskPrimitives_; }

private:
    static constexpr float kNodeCost = 1.0f;       // visiting a wide node
    static constexpr float kPrimitiveCost = 0.3f;  // one primitive test (the paper's ratio)
    static constexpr std::uint8_t kLeaf = 0, kInterior = 1;  // choices; 2 + k: split, k slots left

    float area(std::uint32_t n) const { return std::max(boxOf(nodes_[n]).halfArea(), 0.0f); }
    struct Costs {
        std::array<float, kWideArity> cost;
        std::uint32_t count;  // primitives below
    };

    std::uint32_t rightChild(std::uint32_t n) const {
        PN_CHECK(nodes_[n].firstOrRight > n + 1 && nodes_[n].firstOrRight < nodes_.size());
        return nodes_[n].firstOrRight;
    }

    // Post-order, so that only the costs along the current path are alive (the choices are kept
    // for every node); the depth is at most PN_BVH_MAX_DEPTH.
    Costs solve(std::uint32_t n) {
        if (nodes_[n].triCount > 0) return decide(n, nullptr, nullptr);
        const Costs l = solve(n + 1), r = solve(rightChild(n));
        return decide(n, &l, &r);
    }

    // The top of the tree above the subtrees the tasks solved (their costs in `solved`).
    Costs solveTop(std::uint32_t n, const std::unordered_map<std::uint32_t, Costs>& solved) {
        if (auto it = solved.find(n); it != solved.end()) return it->second;
        const Costs l = solveTop(n + 1, solved), r = solveTop(rightChild(n), solved);
        return decide(n, &l, &r);
    }

    // Primitives below n, from its first and last leaves (the builder numbers leaves in order):
    // only where to cut the tree into tasks depends on it.
    std::uint32_t spanOf(std::uint32_t n) const {
        std::uint32_t first = n, last = n;
        while (nodes_[first].triCount == 0) first = rightChild(first) > 0 ? first + 1 : first;
        while (nodes_[last].triCount == 0) last = rightChild(last);
        return nodes_[last].firstOrRight + nodes_[last].triCount - nodes_[first].firstOrRight;
    }
    void collectSmallSubtrees(std::uint32_t n, std::vector<std::uint32_t>& out) const {
        if (nodes_[n].triCount > 0 || spanOf(n) < taskPrimitives_) {
            out.push_back(n);
            return;
        }
        collectSmallSubtrees(n + 1, out);
        collectSmallSubtrees(rightChild(n), out);
    }

    std::uint32_t solveAll() {
        if (taskPrimitives_ == 0) return solve(0).count;
        std::vector<std::uint32_t> subtrees;
        collectSmallSubtrees(0, subtrees);
        std::vector<Costs> costs(subtrees.size());
        TaskGroup tasks;
        tasks.run([&] {
            for (std::size_t k = 0; k < subtrees.size(); ++k)
                tasks.spawn([&, k] { costs[k] = solve(subtrees[k]); });
        });
        std::unordered_map<std::uint32_t, Costs> solved;
        for (std::size_t k = 0; k < subtrees.size(); ++k) solved.emplace(subtrees[k], costs[k]);
        return solveTop(0, solved).count;
    }

    // Node n's costs and choices, given its children's (null for a leaf).
    Costs decide(std::uint32_t n, const Costs* l, const Costs* r) {
        const shader::BvhNode& node = nodes_[n];
        if (node.triCount > std::uint32_t(kWideMaxBinaryLeaf))
            throw Error("the wide BVH takes binary leaves of at most " +
                        std::to_string(kWideMaxBinaryLeaf) + " primitives, not " +
                        std::to_string(node.triCount));
        float splitCost[kWideArity] = {};  // [i]: the children sharing i + 1 slots
        int bestSplit[kWideArity] = {};
        std::uint32_t count = node.triCount;
        if (node.triCount == 0) {
            const auto& left = l->cost;
            const auto& right = r->cost;
            count = l->count + r->count;
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
        count_[n] = count;
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

    // wideCount_ of the wide subtree headed by b, and of every head below it.
    std::uint32_t countWide(std::uint32_t b) {
        std::uint32_t count = 1;
        for (const Entry& e : entries(b))
            if (e.interior) count += countWide(e.binary);
        wideCount_[b] = count;
        return count;
    }
    // The heads below large ones as tasks, then the large heads from their counts.
    void collectSmallHeads(std::uint32_t b, std::vector<std::uint32_t>& out) const {
        if (!large(b)) {
            out.push_back(b);
            return;
        }
        for (const Entry& e : entries(b))
            if (e.interior) collectSmallHeads(e.binary, out);
    }
    std::uint32_t sumLargeHeads(std::uint32_t b) {
        if (!large(b)) return wideCount_[b];
        std::uint32_t count = 1;
        for (const Entry& e : entries(b))
            if (e.interior) count += sumLargeHeads(e.binary);
        wideCount_[b] = count;
        return count;
    }
    void countAll() {
        if (!large(0)) {
            countWide(0);
            return;
        }
        std::vector<std::uint32_t> heads;
        collectSmallHeads(0, heads);
        TaskGroup tasks;
        tasks.run([&] {
            for (std::uint32_t b : heads) tasks.spawn([this, b] { countWide(b); });
        });
        sumLargeHeads(0);
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
    // Per binary node, all written before they are read (uninitialised: no serial first touch).
    BigBuffer<std::array<std::uint8_t, kWideArity>> choice_;
    BigBuffer<std::uint8_t> split_;        // the best split of a node's children over eight slots
    BigBuffer<std::uint32_t> count_;       // primitives below
    BigBuffer<std::uint32_t> wideCount_;   // wideNodes(), for the binary nodes that head wide ones
    std::uint32_t taskPrimitives_;
    std::uint32_t rootCount_ = 0;
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

namespace {

// Writes the wide nodes and the new primitive order. Their places are those of a serial
// depth-first emission in which each node's interior children get consecutive indices at the end
// of the array and are then expanded last slot first, each subtree before the next; with every
// subtree's node and primitive counts known in advance, subtrees can be emitted in any order.
class Emitter {
public:
    Emitter(const Collapser& collapser, const std::vector<shader::BvhNode>& binary,
            std::vector<shader::WideNode>& nodes, BigBuffer<std::uint32_t>& newOrder)
        : collapser_(collapser), binary_(binary), nodes_(nodes), newOrder_(newOrder) {}

    struct Place {
        std::uint32_t wide, binary, depth;
        std::uint32_t firstChild;      // where its subtree's nodes start (its own is already placed)
        std::uint32_t firstPrimitive;  // where its subtree's primitives start in the new order
    };

    void emit(const Place& p, TaskGroup* tasks) {
        const Entries entries = collapser_.entries(p.binary);
        const SlotOf slotOf = assignSlots(entries, boxOf(binary_[p.binary]));
        shader::WideNode node = encodeNode(entries, slotOf);
        // Leaves' primitives in entry order (the pieces of one binary leaf stay together), then
        // the interior children in slot order, contiguous.
        node.primBase = p.firstPrimitive;
        std::uint32_t offset = 0;
        for (std::size_t k = 0; k < entries.size(); ++k) {
            if (entries[k].interior) continue;
            PN_CHECK(offset + entries[k].count <= std::uint32_t(kWideArity * kWideLeafPrimitives));
            PN_CHECK(std::size_t(p.firstPrimitive) + offset + entries[k].count <= newOrder_.size());
            setByte(node.meta, slotOf[k], (unaryCount(entries[k].count) << 5) | offset);
            for (std::uint32_t j = 0; j < entries[k].count; ++j)
                newOrder_[p.firstPrimitive + offset++] = entries[k].first + j;
        }
        node.childBase = p.firstChild;
        std::array<std::uint32_t, kWideArity> children{};
        std::uint32_t childCount = 0, interiorMask = 0;
        for (int s = 0; s < kWideArity; ++s) {
            for (std::size_t k = 0; k < entries.size(); ++k) {
                if (slotOf[k] != s || !entries[k].interior) continue;
                interiorMask |= 1u << s;
                setByte(node.meta, s, 0x38u | std::uint32_t(s));
                children[childCount++] = entries[k].binary;
            }
        }
        node.exponentsMask |= interiorMask << 24;
        nodes_[p.wide] = node;
        std::uint32_t depth = maxDepth_.load(std::memory_order_relaxed);
        while (p.depth > depth && !maxDepth_.compare_exchange_weak(depth, p.depth)) {
        }
        std::uint32_t nextNode = p.firstChild + childCount, nextPrimitive = p.firstPrimitive + offset;
        for (std::uint32_t i = childCount; i-- > 0;) {
            const Place child{p.firstChild + i, children[i], p.depth + 1, nextNode, nextPrimitive};
            PN_CHECK(child.wide < nodes_.size());
            nextNode += collapser_.wideNodes(children[i]) - 1;
            nextPrimitive += collapser_.primitives(children[i]);
            if (tasks && collapser_.large(p.binary))
                tasks->spawn([this, child, tasks] { emit(child, tasks); });
            else
                emit(child, tasks);
        }
    }

    std::uint32_t maxDepth() const { return maxDepth_.load(); }

private:
    const Collapser& collapser_;
    const std::vector<shader::BvhNode>& binary_;
    std::vector<shader::WideNode>& nodes_;
    BigBuffer<std::uint32_t>& newOrder_;
    std::atomic<std::uint32_t> maxDepth_{0};
};

constexpr std::size_t kRenumberChunk = 64 * 1024;

}  // namespace

WideBvh collapseToWide(Bvh& bvh, const CollapseOptions& options) {
    WideBvh out;
    if (bvh.nodes.empty()) return out;
    const Collapser collapser(bvh.nodes, options.taskPrimitives);
    const std::size_t count = bvh.primOrder.size();
    PN_CHECK(collapser.primitives(0) == count);
    BigBuffer<std::uint32_t> newOrder(count);  // newOrder[k] = old leaf-order position of the k-th primitive
    reserveHuge(out.nodes, collapser.wideNodes(0));
    out.nodes.resize(collapser.wideNodes(0));
    Emitter emitter(collapser, bvh.nodes, out.nodes, newOrder);
    const Emitter::Place root{0, 0, 1, 1, 0};
    if (collapser.large(0)) {
        TaskGroup tasks;
        tasks.run([&] { emitter.emit(root, &tasks); });
    } else {
        emitter.emit(root, nullptr);
    }
    out.maxDepth = emitter.maxDepth();

    // The binary tree in the new order: each binary leaf's primitives stayed consecutive.
    BigBuffer<std::uint32_t> newPosition(count);
    parallelFor(count, kRenumberChunk, [&](std::size_t lo, std::size_t hi) {
        for (std::size_t k = lo; k < hi; ++k) {
            PN_CHECK(newOrder[k] < count);
            newPosition[newOrder[k]] = std::uint32_t(k);
        }
    });
    parallelFor(bvh.nodes.size(), kRenumberChunk, [&](std::size_t lo, std::size_t hi) {
        for (std::size_t i = lo; i < hi; ++i) {
            shader::BvhNode& n = bvh.nodes[i];
            if (n.triCount == 0) continue;
            const std::uint32_t first = newPosition[n.firstOrRight];
            for (std::uint32_t j = 1; j < n.triCount; ++j)
                PN_CHECK(newPosition[n.firstOrRight + j] == first + j);
            n.firstOrRight = first;
        }
    });
    std::vector<std::uint32_t> primOrder = hugeVector<std::uint32_t>(count);
    parallelFor(count, kRenumberChunk, [&](std::size_t lo, std::size_t hi) {
        for (std::size_t k = lo; k < hi; ++k) primOrder[k] = bvh.primOrder[newOrder[k]];
    });
    bvh.primOrder = std::move(primOrder);
    return out;
}

}  // namespace penumbra::bvh
