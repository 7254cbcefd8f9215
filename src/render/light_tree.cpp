#include "render/light_tree.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

constexpr int kBins = 12;

float safeAcos(float c) { return std::acos(std::clamp(c, -1.0f, 1.0f)); }

// v turned by `radians` about the unit axis (Rodrigues' formula).
Vec3 rotateAbout(Vec3 v, Vec3 axis, float radians) {
    const float c = std::cos(radians), s = std::sin(radians);
    return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1.0f - c));
}

struct Cone {
    Vec3 axis;
    float cosTheta;
};

// The smallest cone holding both cones (pbrt-v4's DirectionCone Union).
Cone unionOf(Cone a, Cone b) {
    const float thetaA = safeAcos(a.cosTheta), thetaB = safeAcos(b.cosTheta);
    const float thetaD = safeAcos(dot(a.axis, b.axis));
    if (std::min(thetaD + thetaB, kPiF) <= thetaA) return a;
    if (std::min(thetaD + thetaA, kPiF) <= thetaB) return b;
    const float thetaO = 0.5f * (thetaA + thetaD + thetaB);
    if (thetaO >= kPiF) return {a.axis, -1.0f};
    const Vec3 turn = cross(a.axis, b.axis);
    if (!(dot(turn, turn) > 1e-12f)) return {a.axis, -1.0f};
    return {normalize(rotateAbout(a.axis, normalize(turn), thetaO - thetaA)), std::cos(thetaO)};
}

// pbrt-v4's surface area orientation heuristic for a node (EvaluateCost): power times the
// measure of the directions it emits into times its surface area, with kr favouring cuts across
// the longest axis.
float orientationCost(const LightBounds& b, float kr) {
    if (!(b.phi > 0)) return 0;
    const float thetaO = safeAcos(b.cosThetaO), thetaE = safeAcos(b.cosThetaE);
    const float thetaW = std::min(thetaO + thetaE, kPiF);
    const float sinO = std::sqrt(std::max(0.0f, 1 - b.cosThetaO * b.cosThetaO));
    const float mOmega = 2 * kPiF * (1 - b.cosThetaO) +
                         kPiF / 2 * (2 * thetaW * sinO - std::cos(thetaO - 2 * thetaW) - 2 * thetaO * sinO + b.cosThetaO);
    return b.phi * mOmega * kr * b.bounds.area();
}

struct Item {
    LightBounds bounds;
    Vec3 centroid;
    std::uint32_t light;
};

class TreeBuilder {
public:
    TreeBuilder(std::span<const LightBounds> lights, std::uint32_t firstRef, std::uint32_t nodeBase, LightTree& out)
        : firstRef_(firstRef), nodeBase_(nodeBase), out_(out) {
        items_.reserve(lights.size());
        for (std::uint32_t i = 0; i < lights.size(); ++i)
            items_.push_back({lights[i], lights[i].bounds.center(), i});
        out_.trails.assign(lights.size(), 0);
        out_.nodes.reserve(2 * lights.size());
    }

    // Writes the subtree over items [begin, end) and returns its bounds: a node's bounds are the
    // union of its children's, so every node holds its children (and every light below it).
    LightBounds build(std::size_t begin, std::size_t end, std::uint64_t trail, std::uint32_t depth) {
        if (end - begin == 1) {
            out_.nodes.push_back(toLightNode(items_[begin].bounds, PN_LIGHT_NODE_LEAF | (firstRef_ + items_[begin].light)));
            out_.trails[items_[begin].light] = trail;
            return items_[begin].bounds;
        }
        LightBounds total;
        for (std::size_t i = begin; i < end; ++i) total = unionOf(total, items_[i].bounds);
        const std::size_t mid = split(begin, end, total, depth);
        const std::size_t self = out_.nodes.size();
        out_.nodes.emplace_back();
        const LightBounds first = build(begin, mid, trail, depth + 1);
        const auto second = static_cast<std::uint32_t>(out_.nodes.size());
        const LightBounds both = unionOf(first, build(mid, end, trail | (std::uint64_t(1) << depth), depth + 1));
        out_.nodes[self] = toLightNode(both, nodeBase_ + second);
        return both;
    }

private:
    // The cheapest of the binned cuts on the three axes; a median cut when the centroids
    // coincide or the depth budget runs short. Returns the first index of the second half.
    std::size_t split(std::size_t begin, std::size_t end, const LightBounds& total, std::uint32_t depth) {
        Aabb centroids;
        for (std::size_t i = begin; i < end; ++i) centroids.grow(items_[i].centroid);
        const Vec3 extent = centroids.extent();
        const std::size_t count = end - begin;
        const bool deep = depth + std::ceil(std::log2(double(count))) >= PN_LIGHT_TREE_MAX_DEPTH - 1;
        float bestCost = std::numeric_limits<float>::infinity();
        int bestAxis = -1, bestBin = 0;
        const Vec3 diagonal = total.bounds.extent();
        for (int axis = 0; axis < 3 && !deep; ++axis) {
            if (!(extent[axis] > 0)) continue;
            std::array<LightBounds, kBins> bins{};
            std::array<std::size_t, kBins> counts{};
            for (std::size_t i = begin; i < end; ++i) {
                const int b = binOf(items_[i].centroid[axis], centroids.lo[axis], extent[axis]);
                bins[b] = unionOf(bins[b], items_[i].bounds);
                ++counts[b];
            }
            const float kr = maxComponent(diagonal) / std::max(diagonal[axis], 1e-20f);
            for (int cut = 1; cut < kBins; ++cut) {
                LightBounds below, above;
                std::size_t nBelow = 0;
                for (int b = 0; b < cut; ++b) below = unionOf(below, bins[b]), nBelow += counts[b];
                for (int b = cut; b < kBins; ++b) above = unionOf(above, bins[b]);
                if (nBelow == 0 || nBelow == count) continue;
                const float cost = orientationCost(below, kr) + orientationCost(above, kr);
                if (cost < bestCost) bestCost = cost, bestAxis = axis, bestBin = cut;
            }
        }
        auto first = items_.begin() + std::ptrdiff_t(begin), last = items_.begin() + std::ptrdiff_t(end);
        if (bestAxis < 0) {
            const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
            auto middle = first + std::ptrdiff_t(count / 2);
            std::nth_element(first, middle, last,
                             [axis](const Item& a, const Item& b) { return a.centroid[axis] < b.centroid[axis]; });
            return begin + count / 2;
        }
        auto middle = std::partition(first, last, [&](const Item& it) {
            return binOf(it.centroid[bestAxis], centroids.lo[bestAxis], extent[bestAxis]) < bestBin;
        });
        return std::size_t(middle - items_.begin());
    }

    static int binOf(float c, float lo, float extent) {
        return std::clamp(int(float(kBins) * (c - lo) / extent), 0, kBins - 1);
    }

    std::vector<Item> items_;
    std::uint32_t firstRef_, nodeBase_;
    LightTree& out_;
};

}  // namespace

LightBounds unionOf(const LightBounds& a, const LightBounds& b) {
    if (!(a.phi > 0)) return b;
    if (!(b.phi > 0)) return a;
    LightBounds u;
    u.bounds = a.bounds;
    u.bounds.grow(b.bounds);
    u.phi = a.phi + b.phi;
    const Cone cone = unionOf(Cone{a.axis, a.cosThetaO}, Cone{b.axis, b.cosThetaO});
    u.axis = cone.axis;
    u.cosThetaO = cone.cosTheta;
    u.cosThetaE = std::min(a.cosThetaE, b.cosThetaE);
    u.twoSided = a.twoSided || b.twoSided;
    return u;
}

LightBounds pointLightBounds(Vec3 position, float intensity) {
    LightBounds b;
    b.bounds.grow(position);
    b.phi = intensity;
    b.cosThetaO = -1.0f;  // every direction
    b.cosThetaE = 0.0f;
    return b;
}

LightBounds spotLightBounds(Vec3 position, Vec3 direction, float intensity, float cosInner, float cosOuter) {
    LightBounds b = pointLightBounds(position, intensity);
    b.axis = normalize(direction);
    // Full strength within the inner cone, fading to nothing at the outer one.
    const float inner = safeAcos(std::max(cosInner, cosOuter)), outer = safeAcos(cosOuter);
    b.cosThetaO = std::cos(inner);
    b.cosThetaE = std::cos(std::max(0.0f, outer - inner));
    return b;
}

shader::LightNode toLightNode(const LightBounds& b, std::uint32_t childOrLight) {
    shader::LightNode n{};
    n.boundsMin = b.bounds.lo;
    n.boundsMax = b.bounds.hi;
    n.phi = b.phi;
    n.axis = b.axis;
    n.cosThetaO = b.cosThetaO;
    n.cosThetaE = b.cosThetaE;
    n.childOrLight = childOrLight;
    n.twoSided = b.twoSided ? 1u : 0u;
    n.sinThetaO = std::sqrt(std::max(0.0f, 1.0f - b.cosThetaO * b.cosThetaO));
    n.minDistance2 = 0.5f * length(b.bounds.extent());
    return n;
}

LightTree buildLightTree(std::span<const LightBounds> lights, std::uint32_t firstRef, std::uint32_t nodeBase) {
    LightTree tree;
    if (lights.empty()) return tree;
    for (const LightBounds& l : lights) PN_CHECK(l.phi > 0 && !l.bounds.empty());
    TreeBuilder builder(lights, firstRef, nodeBase, tree);
    builder.build(0, lights.size(), 0, 0);
    return tree;
}

namespace {

// Writes the binary tree's nodes as records of the shaders' layout, children side by side.
class TreeCompactor {
public:
    explicit TreeCompactor(const LightTree& tree) : tree_(tree) { out_.resize(1); }

    std::vector<shader::LightTreeNode> run() {
        write(0, 0);
        return std::move(out_);
    }

private:
    void write(std::uint32_t node, std::uint32_t record) {
        const shader::LightNode& n = tree_.nodes[node];
        if (n.childOrLight & PN_LIGHT_NODE_LEAF) {
            const std::uint32_t ref = n.childOrLight & ~PN_LIGHT_NODE_LEAF;
            PN_CHECK(ref <= PN_LIGHT_NODE_INDEX);
            out_[record] = compact(n, PN_LIGHT_NODE_LEAF | ref);
            return;
        }
        const auto pair = static_cast<std::uint32_t>(out_.size());
        PN_CHECK(pair < PN_LIGHT_NODE_INDEX);
        out_.resize(out_.size() + 2);
        out_[record] = compact(n, pair);
        write(node + 1, pair);
        write(n.childOrLight, pair + 1);
    }

    static shader::LightTreeNode compact(const shader::LightNode& n, std::uint32_t childOrLight) {
        shader::LightTreeNode c{};
        const Vec3 halfDiagonal = 0.5f * (n.boundsMax - n.boundsMin);
        c.center = n.boundsMin + halfDiagonal;
        c.radius = length(halfDiagonal);
        c.axis = n.axis;
        c.phi = n.phi;
        c.cosThetaO = n.cosThetaO;
        c.sinThetaO = n.sinThetaO;
        c.cosThetaE = n.cosThetaE;
        c.childOrLight = childOrLight | (n.twoSided ? PN_LIGHT_NODE_TWO_SIDED : 0u);
        return c;
    }

    const LightTree& tree_;
    std::vector<shader::LightTreeNode> out_;
};

}  // namespace

std::vector<shader::LightTreeNode> compactLightTree(const LightTree& tree) {
    if (tree.nodes.empty()) return {};
    return TreeCompactor(tree).run();
}

LightTreeDepth lightTreeDepth(std::span<const shader::LightTreeNode> records) {
    LightTreeDepth out;
    if (records.empty()) return out;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{0, 1}};  // (record, depth; root 1)
    double sum = 0;
    std::size_t leaves = 0;
    while (!stack.empty()) {
        const auto [record, depth] = stack.back();
        stack.pop_back();
        const std::uint32_t child = records[record].childOrLight;
        if (child & PN_LIGHT_NODE_LEAF) {
            out.max = std::max(out.max, depth);
            sum += depth;
            ++leaves;
            continue;
        }
        const std::uint32_t pair = child & PN_LIGHT_NODE_INDEX;
        PN_CHECK(pair + 1 < records.size());
        stack.push_back({pair, depth + 1});
        stack.push_back({pair + 1, depth + 1});
    }
    out.mean = sum / double(leaves);
    return out;
}

}  // namespace penumbra
