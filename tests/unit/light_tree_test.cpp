// The light BVH (render/light_tree.h) and the light list (render/light_list.h): bounds that hold
// what they bound, every light reachable along its bit trail, and the top-level entries.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "render/light_list.h"
#include "render/light_tree.h"

namespace penumbra {
namespace {

float angleBetween(Vec3 a, Vec3 b) { return std::acos(std::clamp(dot(normalize(a), normalize(b)), -1.0f, 1.0f)); }

Vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    return normalize(Vec3{g(rng), g(rng), g(rng)});
}

LightBounds randomTriangleLight(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-10, 10), size(0.01f, 1.0f), power(0.1f, 100.0f);
    LightBounds b;
    const Vec3 c{u(rng), u(rng), u(rng)};
    b.bounds.grow(c);
    b.bounds.grow(c + Vec3{size(rng), size(rng), size(rng)});
    b.phi = power(rng);
    b.axis = randomUnit(rng);
    b.cosThetaO = 1.0f;
    b.cosThetaE = 0.0f;
    return b;
}

// Every direction within thetaO of the inner cone's axis is within thetaO of the outer cone's.
void expectConeHolds(const LightBounds& outer, const LightBounds& inner) {
    const float thetaOuter = std::acos(std::clamp(outer.cosThetaO, -1.0f, 1.0f));
    const float thetaInner = std::acos(std::clamp(inner.cosThetaO, -1.0f, 1.0f));
    EXPECT_LE(angleBetween(outer.axis, inner.axis) + thetaInner, thetaOuter + 1e-3f);
    EXPECT_LE(outer.cosThetaE, inner.cosThetaE + 1e-6f);
}

TEST(LightTree, UnionHoldsBothCones) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> angle(0, 1.5f);
    for (int i = 0; i < 1000; ++i) {
        LightBounds a = randomTriangleLight(rng), b = randomTriangleLight(rng);
        a.cosThetaO = std::cos(angle(rng));
        b.cosThetaO = std::cos(angle(rng));
        const LightBounds u = unionOf(a, b);
        if (u.cosThetaO > -1.0f) {  // -1 holds everything
            expectConeHolds(u, a);
            expectConeHolds(u, b);
        }
        EXPECT_FLOAT_EQ(u.phi, a.phi + b.phi);
    }
}

struct Walk {
    int leaves = 0;
    std::uint32_t maxDepth = 0;
};

// Checks node `index` (buffer index base + i) against its children; returns its bounds.
void checkSubtree(const LightTree& t, std::uint32_t base, std::uint32_t index, std::uint32_t depth, Walk& walk) {
    const shader::LightNode& n = t.nodes[index - base];
    walk.maxDepth = std::max(walk.maxDepth, depth);
    if (n.childOrLight & PN_LIGHT_NODE_LEAF) {
        ++walk.leaves;
        return;
    }
    for (std::uint32_t child : {index + 1, n.childOrLight}) {
        const shader::LightNode& c = t.nodes[child - base];
        for (int k = 0; k < 3; ++k) {
            EXPECT_LE(n.boundsMin[k], c.boundsMin[k]);
            EXPECT_GE(n.boundsMax[k], c.boundsMax[k]);
        }
        const float thetaN = std::acos(std::clamp(n.cosThetaO, -1.0f, 1.0f));
        const float thetaC = std::acos(std::clamp(c.cosThetaO, -1.0f, 1.0f));
        if (n.cosThetaO > -1.0f) {
            EXPECT_LE(angleBetween(n.axis, c.axis) + thetaC, thetaN + 1e-3f);
        }
        checkSubtree(t, base, child, depth + 1, walk);
    }
    EXPECT_NEAR(n.phi, t.nodes[index + 1 - base].phi + t.nodes[n.childOrLight - base].phi, 1e-4f * n.phi);
}

TEST(LightTree, BoundsHoldChildrenAndTrailsLeadToEveryLight) {
    std::mt19937 rng(11);
    std::vector<LightBounds> lights;
    for (int i = 0; i < 3000; ++i) lights.push_back(randomTriangleLight(rng));
    lights.push_back(pointLightBounds({1, 2, 3}, 5.0f));
    lights.push_back(spotLightBounds({0, 5, 0}, {0, -1, 0}, 50.0f, std::cos(0.3f), std::cos(0.5f)));
    const std::uint32_t firstRef = 4, base = 7;
    const LightTree t = buildLightTree(lights, firstRef, base);
    ASSERT_EQ(t.trails.size(), lights.size());
    Walk walk;
    checkSubtree(t, base, base, 0, walk);
    EXPECT_EQ(walk.leaves, int(lights.size()));
    EXPECT_LT(walk.maxDepth, PN_LIGHT_TREE_MAX_DEPTH);
    EXPECT_LT(walk.maxDepth, 40u);  // 3002 lights: a sane tree is far from degenerate
    for (std::uint32_t i = 0; i < lights.size(); ++i) {
        std::uint32_t node = base;
        for (std::uint32_t depth = 0; !(t.nodes[node - base].childOrLight & PN_LIGHT_NODE_LEAF); ++depth)
            node = (t.trails[i] >> depth) & 1 ? t.nodes[node - base].childOrLight : node + 1;
        ASSERT_EQ(t.nodes[node - base].childOrLight, PN_LIGHT_NODE_LEAF | (firstRef + i)) << "light " << i;
        EXPECT_FLOAT_EQ(t.nodes[node - base].phi, lights[i].phi);
    }
}

// Walks the binary tree and its records for the shaders side by side: each record must bound its
// node (the box's sphere, the same cone and power) and keep the child order.
void checkCompact(const LightTree& t, const std::vector<shader::LightTreeNode>& records, std::uint32_t node,
                  std::uint32_t record, int& leaves) {
    const shader::LightNode& n = t.nodes[node];
    const shader::LightTreeNode& c = records.at(record);
    for (Vec3 corner : {n.boundsMin, n.boundsMax, Vec3{n.boundsMin.x, n.boundsMax.y, n.boundsMin.z}})
        EXPECT_LE(length(corner - c.center), c.radius * (1 + 1e-6f) + 1e-6f);
    EXPECT_NEAR(c.radius, 0.5f * length(n.boundsMax - n.boundsMin), 1e-5f * (1 + c.radius));  // and tightly
    EXPECT_EQ(c.axis, n.axis);
    EXPECT_EQ(c.phi, n.phi);
    EXPECT_EQ(c.cosThetaO, n.cosThetaO);
    EXPECT_NEAR(c.sinThetaO, std::sqrt(std::max(0.0f, 1 - n.cosThetaO * n.cosThetaO)), 1e-6f);
    EXPECT_EQ(c.cosThetaE, n.cosThetaE);
    EXPECT_EQ((c.childOrLight & PN_LIGHT_NODE_TWO_SIDED) != 0, n.twoSided != 0);
    if (n.childOrLight & PN_LIGHT_NODE_LEAF) {
        EXPECT_EQ(c.childOrLight & (PN_LIGHT_NODE_LEAF | PN_LIGHT_NODE_INDEX), n.childOrLight);
        ++leaves;
        return;
    }
    const std::uint32_t pair = c.childOrLight & PN_LIGHT_NODE_INDEX;
    checkCompact(t, records, node + 1, pair, leaves);
    checkCompact(t, records, n.childOrLight, pair + 1, leaves);
}

TEST(LightTree, ShaderRecordsBoundTheirNodesAndKeepTheTrails) {
    std::mt19937 rng(5);
    std::vector<LightBounds> lights;
    for (int i = 0; i < 2000; ++i) lights.push_back(randomTriangleLight(rng));
    lights[7].twoSided = true;
    lights.push_back(pointLightBounds({1, 2, 3}, 5.0f));
    lights.push_back(spotLightBounds({0, 5, 0}, {0, -1, 0}, 50.0f, std::cos(0.3f), std::cos(0.5f)));
    const std::uint32_t firstRef = 3;
    const LightTree t = buildLightTree(lights, firstRef, 0);
    const std::vector<shader::LightTreeNode> records = compactLightTree(t);
    ASSERT_EQ(records.size(), t.nodes.size());
    int leaves = 0;
    checkCompact(t, records, 0, 0, leaves);
    EXPECT_EQ(leaves, int(lights.size()));
    for (std::uint32_t i = 0; i < lights.size(); ++i) {
        std::uint32_t record = 0;
        for (std::uint32_t depth = 0; !(records[record].childOrLight & PN_LIGHT_NODE_LEAF); ++depth)
            record = (records[record].childOrLight & PN_LIGHT_NODE_INDEX) + ((t.trails[i] >> depth) & 1);
        ASSERT_EQ(records[record].childOrLight & PN_LIGHT_NODE_INDEX, firstRef + i) << "light " << i;
    }
    const LightTreeDepth depth = lightTreeDepth(records);
    EXPECT_GE(depth.mean, 1 + std::log2(double(lights.size())) - 1e-9);  // no binary tree is shallower (root: 1)
    EXPECT_LT(depth.max, 40u);
    EXPECT_TRUE(compactLightTree(LightTree{}).empty());
    // Two lights: a root and two leaves, at depth 2 as bvh::treeDepth counts (root 1).
    const std::vector<LightBounds> two{pointLightBounds({0, 0, 0}, 1.0f), pointLightBounds({1, 0, 0}, 1.0f)};
    const LightTreeDepth small = lightTreeDepth(compactLightTree(buildLightTree(two, 0, 0)));
    EXPECT_EQ(small.max, 2u);
    EXPECT_EQ(small.mean, 2.0);
}

TEST(LightTree, CoincidentLightsStillSplitAndStayShallow) {
    std::vector<LightBounds> lights(5000, pointLightBounds({1, 1, 1}, 1.0f));
    const LightTree t = buildLightTree(lights, 0, 0);
    Walk walk;
    checkSubtree(t, 0, 0, 0, walk);
    EXPECT_EQ(walk.leaves, 5000);
    EXPECT_LE(walk.maxDepth, 13u);  // median cuts: ceil(log2 5000)
}

TEST(LightList, TopLevelHoldsTheEnvironmentDirectionalAndMovingLights) {
    std::vector<shader::PunctualLight> punctual(3);
    punctual[0].type = PN_LIGHT_POINT;
    punctual[0].intensity = Vec3{1.0f};
    punctual[1].type = PN_LIGHT_DIRECTIONAL;
    punctual[1].intensity = Vec3{2.0f};
    punctual[1].direction = {0, -1, 0};
    punctual[2].type = PN_LIGHT_POINT;
    punctual[2].intensity = Vec3{3.0f};
    punctual[2].position = {4, 5, 6};
    LightListInput in;
    in.punctual = punctual;
    in.punctualMoves = {false, false, true};
    in.environment = true;
    in.triangles.push_back({9, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 2.0f});
    const LightList list = buildLightList(in);
    ASSERT_EQ(list.topCount, 3u);
    EXPECT_EQ(list.refs[0].type, PN_LIGHTREF_ENVIRONMENT);
    EXPECT_EQ(list.refs[1].index, 1u);  // the directional light
    EXPECT_EQ(list.refs[2].index, 2u);  // the moving one, bounded by its own node
    EXPECT_EQ(list.nodes[2].boundsMin, (Vec3{4, 5, 6}));
    EXPECT_EQ(topEntryOfPunctual(list.refs, list.topCount, 2), 2u);
    EXPECT_FALSE(topEntryOfPunctual(list.refs, list.topCount, 0).has_value());
    // The tree holds the fixed point light and the triangle; the triangle's slot knows its ref.
    EXPECT_EQ(list.refs.size(), 5u);
    ASSERT_EQ(list.primitiveLights.size(), 1u);
    EXPECT_EQ(list.primitiveLights[0].first, 9u);
    EXPECT_EQ(list.refs[list.primitiveLights[0].second].type, PN_LIGHTREF_TRIANGLE);
    ASSERT_EQ(list.nodes.size(), list.topCount);
    ASSERT_EQ(list.tree.size(), 3u);  // the root and its two leaves
    EXPECT_FLOAT_EQ(list.tree[0].phi, 1.0f + 2.0f * 0.5f);  // point I + radiance x area
}

}  // namespace
}  // namespace penumbra
