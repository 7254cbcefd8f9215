// The light grid (render/light_grid.h): alias tables that realise exactly the masses the shaders
// read back for MIS, and cell tables that never drop a cluster the tree walk could pick at any
// point of the cell with any normal of the bin.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <random>

#include "core/error.h"
#include "render/light_grid.h"
#include "render/light_tree.h"
#include "shared/light_importance.h"

namespace penumbra {
namespace {

constexpr double kOne = double(1u << PN_LIGHT_GRID_MASS_BITS);

Vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    return normalize(Vec3{g(rng), g(rng), g(rng)});
}

TEST(LightGrid, AliasTablesRealiseTheirMassesExactly) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    for (int trial = 0; trial < 200; ++trial) {
        const std::size_t count = 1 + trial % 40;
        std::vector<double> weights(count);
        for (double& w : weights) w = u(rng) < 0.3 ? 0.0 : std::pow(u(rng), 8.0) * 1e3;  // zeros and a wide range
        const std::vector<std::uint32_t> table = lightGridAliasTable(weights);
        double total = 0, masses = 0;
        for (double w : weights) total += w;
        for (std::uint32_t k = 0; k < count; ++k) {
            const double mass = table[2 * k + 1];
            masses += mass;
            EXPECT_EQ(weights[k] > 0, mass > 0) << "trial " << trial << " entry " << k;
            if (total == 0) continue;  // every mass 0: the shaders find no light whatever they draw
            EXPECT_EQ(lightGridRealisedProbability(table, k), mass / (kOne * double(count))) << "trial " << trial;
            // Rounding: each mass floors, the largest takes up what that left (at most count).
            EXPECT_NEAR(mass / (kOne * double(count)), weights[k] / total, (count + 1.0) / (kOne * double(count)));
        }
        EXPECT_EQ(masses, total > 0 ? kOne * double(count) : 0.0);
    }
}

TEST(LightGrid, AllZeroWeightsGiveAnEmptyTable) {
    const std::vector<double> zeros(7, 0.0);
    const std::vector<std::uint32_t> table = lightGridAliasTable(zeros);
    for (std::uint32_t k = 0; k < 7; ++k) EXPECT_EQ(table[2 * k + 1], 0u);
}

// Emitters of many sizes, facing every way, some with wide cones (spot and point lights).
std::vector<LightBounds> randomLights(std::mt19937& rng, int count) {
    std::uniform_real_distribution<float> u(-10, 10), size(0.01f, 2.0f), power(0.1f, 100.0f);
    std::vector<LightBounds> lights;
    for (int i = 0; i < count; ++i) {
        const Vec3 c{u(rng), u(rng), u(rng)};
        if (i % 9 == 0) {
            lights.push_back(spotLightBounds(c, randomUnit(rng), power(rng), std::cos(0.3f), std::cos(0.6f)));
            continue;
        }
        LightBounds b;
        b.bounds.grow(c);
        b.bounds.grow(c + Vec3{size(rng), size(rng), size(rng)});
        b.phi = power(rng);
        b.axis = randomUnit(rng);
        b.twoSided = i % 5 == 0;
        lights.push_back(b);
    }
    return lights;
}

// Which tree node the walk is at after `level` steps along trail prefix `prefix` (or the leaf above it).
std::uint32_t recordAt(std::span<const shader::LightTreeNode> tree, std::uint32_t prefix, std::uint32_t level) {
    std::uint32_t record = 0;
    for (std::uint32_t d = 0; d < level && !(tree[record].childOrLight & PN_LIGHT_NODE_LEAF); ++d)
        record = (tree[record].childOrLight & PN_LIGHT_NODE_INDEX) + ((prefix >> d) & 1u);
    return record;
}

// Each cluster's own alias table holds exactly the lights below it, each with the probability
// power over the cluster's power that the walk below it would give (to the masses' rounding), and
// the mass MIS reads back for a light is the one its table realises.
void expectClusterPicksFollowPower(std::span<const std::uint32_t> grid, std::span<const shader::LightTreeNode> tree) {
    const shader::LightGridHeader header = lightGridHeader(grid);
    const std::uint32_t clusters = header.clusterCount;
    const std::uint32_t* clusterWords = &grid[PN_LIGHT_GRID_PREFIXES + (1u << header.levels)];
    int aliased = 0;
    for (std::uint32_t c = 0; c < clusters; ++c) {
        const std::uint32_t* w = &clusterWords[PN_LIGHT_GRID_CLUSTER_WORDS * c];
        if (w[0] & PN_LIGHT_NODE_LEAF) {
            EXPECT_EQ(w[3], 0u);  // a single light: nothing to draw
            continue;
        }
        ASSERT_GT(w[3], 1u);
        ++aliased;
        // The lights below the cluster's node, with their power.
        std::map<std::uint32_t, double> below;
        std::vector<std::uint32_t> stack{w[0] & PN_LIGHT_NODE_INDEX};
        stack.push_back(stack.back() + 1);
        double total = 0;
        while (!stack.empty()) {
            const shader::LightTreeNode& n = tree[stack.back()];
            stack.pop_back();
            if (n.childOrLight & PN_LIGHT_NODE_LEAF) {
                below[n.childOrLight & PN_LIGHT_NODE_INDEX] = n.phi;
                total += n.phi;
            } else {
                stack.push_back(n.childOrLight & PN_LIGHT_NODE_INDEX);
                stack.push_back((n.childOrLight & PN_LIGHT_NODE_INDEX) + 1);
            }
        }
        ASSERT_EQ(below.size(), w[3]);
        std::vector<std::uint32_t> table;  // the cluster's entries as a plain alias table (threshold, mass)
        for (std::uint32_t j = 0; j < w[3]; ++j) {
            const std::uint32_t ref = grid[w[2] + 2 * j + 1];
            ASSERT_EQ(below.count(ref), 1u) << "cluster " << c << " entry " << j;
            table.push_back(grid[w[2] + 2 * j]);
            table.push_back(grid[header.firstMass + ref]);
        }
        for (std::uint32_t j = 0; j < w[3]; ++j) {
            const std::uint32_t ref = grid[w[2] + 2 * j + 1];
            const double p = double(table[2 * j + 1]) / (kOne * w[3]);
            EXPECT_EQ(lightGridRealisedProbability(table, j), p) << "cluster " << c << " light " << ref;
            EXPECT_NEAR(p, below[ref] / total, (w[3] + 1.0) / (kOne * w[3])) << "cluster " << c << " light " << ref;
        }
    }
    EXPECT_GT(aliased, 0);
}

class LightGridLevels : public testing::TestWithParam<std::uint32_t> {};

TEST_P(LightGridLevels, CellTablesKeepEveryClusterThatCouldLightAPointOfTheCell) {
    std::mt19937 rng(17);
    const std::uint32_t levels = GetParam();
    const std::vector<LightBounds> lights = randomLights(rng, 400);
    const std::vector<shader::LightTreeNode> tree = compactLightTree(buildLightTree(lights, 0, 0));
    Aabb bounds;
    bounds.grow(Vec3{-12, -12, -3});
    bounds.grow(Vec3{12, 12, 3});
    LightGridOptions options;
    options.maxWords = 1u << 18;
    options.levels = levels;
    const std::vector<std::uint32_t> grid = buildLightGrid(tree, bounds, options);
    ASSERT_GT(grid.size(), std::size_t(PN_LIGHT_GRID_PREFIXES));
    const shader::LightGridHeader header = lightGridHeader(grid);
    ASSERT_EQ(header.levels, levels);
    const std::uint32_t clusters = header.clusterCount, prefixes = 1u << levels;
    ASSERT_GT(clusters, prefixes / 2);
    ASSERT_LE(clusters, prefixes);
    const std::uint32_t* clusterWords = &grid[PN_LIGHT_GRID_PREFIXES + prefixes];
    // Every trail prefix leads to its cluster's node.
    for (std::uint32_t prefix = 0; prefix < prefixes; ++prefix) {
        const std::uint32_t c = grid[PN_LIGHT_GRID_PREFIXES + prefix];
        ASSERT_LT(c, clusters);
        const std::uint32_t level = clusterWords[PN_LIGHT_GRID_CLUSTER_WORDS * c + 1];
        EXPECT_EQ(clusterWords[PN_LIGHT_GRID_CLUSTER_WORDS * c], tree[recordAt(tree, prefix, level)].childOrLight);
    }
    expectClusterPicksFollowPower(grid, tree);
    std::uniform_real_distribution<float> ux(-12, 12), uz(-3, 3);
    int checked = 0;
    for (int k = 0; k < 20000; ++k) {
        const Vec3 p{ux(rng), ux(rng), uz(rng)}, n = randomUnit(rng);
        const std::uint32_t table = lightGridTableAt(grid, p, n);
        ASSERT_NE(table, PN_NO_HIT);
        // The tree's weight against the top-level lights: the root's bound over the cell and bin.
        const std::uint32_t index = (table - header.firstTable) / (2 * clusters);
        float treeWeight;
        std::memcpy(&treeWeight, &grid[header.firstTree + index], 4);
        const shader::LightTreeNode& root = tree[0];
        const shader::LightCluster rootBounds{root.center,    root.radius,    root.axis,      root.phi,
                                              root.cosThetaO, root.sinThetaO, root.cosThetaE, (root.childOrLight & PN_LIGHT_NODE_TWO_SIDED) != 0};
        if (shader::clusterImportance(rootBounds, p, n) > 0) {
            ASSERT_GT(treeWeight, 0.0f);
        }
        for (std::uint32_t prefix = 0; prefix < prefixes; ++prefix) {
            const std::uint32_t c = grid[PN_LIGHT_GRID_PREFIXES + prefix];
            const shader::LightTreeNode& node = tree[recordAt(tree, prefix, clusterWords[PN_LIGHT_GRID_CLUSTER_WORDS * c + 1])];
            const shader::LightCluster exact{node.center,    node.radius,    node.axis,      node.phi,
                                             node.cosThetaO, node.sinThetaO, node.cosThetaE, (node.childOrLight & PN_LIGHT_NODE_TWO_SIDED) != 0};
            if (shader::clusterImportance(exact, p, n) <= 0) continue;
            ++checked;
            ASSERT_GT(grid[table + 2 * c + 1], 0u) << "point (" << p.x << ", " << p.y << ", " << p.z << ") cluster " << c;
        }
    }
    EXPECT_GT(checked, 100000);
    // Off the grid, and without a normal, the walk weighs the levels itself.
    EXPECT_EQ(lightGridTableAt(grid, Vec3{0, 0, 50}, Vec3{0, 0, 1}), PN_NO_HIT);
    EXPECT_EQ(lightGridTableAt(grid, Vec3{0, 0, 0}, Vec3{0, 0, 0}), PN_NO_HIT);
}

INSTANTIATE_TEST_SUITE_P(LightGrid, LightGridLevels, testing::Values(5u, 7u));

TEST(LightGrid, ShallowTreesKeepTheWalk) {
    std::mt19937 rng(5);
    const std::vector<shader::LightTreeNode> tree = compactLightTree(buildLightTree(randomLights(rng, 20), 0, 0));
    Aabb bounds;
    bounds.grow(Vec3{-12});
    bounds.grow(Vec3{12});
    EXPECT_TRUE(buildLightGrid(tree, bounds).empty());  // 20 lights: the walk already weighs each
    EXPECT_TRUE(buildLightGrid({}, bounds).empty());
}

// Fewer words than a header is no grid: reading one is an error, not a read past the end.
TEST(LightGrid, ShortWordsHoldNoHeader) {
    const std::vector<std::uint32_t> words(PN_LIGHT_GRID_PREFIXES - 1, 0u);
    EXPECT_THROW(lightGridHeader(words), Error);
}

TEST(LightGrid, BoundsBeyondFloatsKeepTheWalk) {
    std::mt19937 rng(8);
    const std::vector<shader::LightTreeNode> tree = compactLightTree(buildLightTree(randomLights(rng, 400), 0, 0));
    Aabb huge;
    huge.grow(Vec3{-3e38f, 0, 0});
    huge.grow(Vec3{3e38f, 1, 1});  // its extent overflows to infinity
    EXPECT_TRUE(buildLightGrid(tree, huge).empty());
    Aabb point;
    point.grow(Vec3{1, 2, 3});  // no extent at all: one cell
    const std::vector<std::uint32_t> grid = buildLightGrid(tree, point);
    ASSERT_FALSE(grid.empty());
    const shader::LightGridHeader header = lightGridHeader(grid);
    EXPECT_EQ(header.cellsX * header.cellsY * header.cellsZ, 1u);
}

}  // namespace
}  // namespace penumbra
