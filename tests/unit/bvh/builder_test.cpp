// Structure and quality of built trees; traversal correctness lives in traverse_test.cpp.
#include "bvh/builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

#include "bvh/stats.h"
#include "bvh/validate.h"
#include "bvh_test_util.h"
#include "core/error.h"
#include "core/parallel.h"
#include "median_split.h"

namespace penumbra::bvh {
namespace {

using test::boxesOf;
using test::randomSoup;

void expectSane(const Bvh& bvh, const std::vector<Aabb>& boxes, const BuildOptions& options) {
    ASSERT_NO_THROW(validate(bvh, boxes));
    BvhStats s = computeStats(bvh, options);
    EXPECT_EQ(s.nodes, bvh.nodes.size());
    EXPECT_LE(s.maxDepth, std::size_t(PN_BVH_MAX_DEPTH));
    EXPECT_LE(s.maxLeafSize, std::size_t(std::max(options.maxLeafSize, 1)));
    // A binary tree whose leaves are all non-empty has exactly one more leaf than interior nodes.
    EXPECT_EQ(s.nodes, 2 * s.leaves - 1);
    EXPECT_NEAR(s.avgLeafSize * double(s.leaves), double(boxes.size()), 1e-6 * boxes.size());
    std::size_t leafPrims = 0;
    for (const auto& n : bvh.nodes) leafPrims += n.triCount;
    EXPECT_EQ(leafPrims, boxes.size());
}

TEST(BvhBuild, EmptyInputGivesNoNodes) {
    Bvh bvh = build({});
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_TRUE(bvh.primOrder.empty());
    EXPECT_NO_THROW(validate(bvh, {}));
    BvhStats s = computeStats(bvh, {});
    EXPECT_EQ(s.nodes, 0u);
    EXPECT_EQ(s.leaves, 0u);
}

TEST(BvhBuild, SinglePrimitiveIsOneLeaf) {
    std::vector<Aabb> boxes{{Vec3(0.0f), Vec3(1.0f)}};
    Bvh bvh = build(boxes);
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_EQ(bvh.nodes[0].triCount, 1u);
    EXPECT_EQ(bvh.nodes[0].firstOrRight, 0u);
    EXPECT_EQ(bvh.primOrder, std::vector<std::uint32_t>{0});
}

TEST(BvhBuild, RandomSoupsAreValid) {
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        for (std::size_t n : {1u, 2u, 3u, 5u, 8u, 17u, 100u, 1000u, 5000u}) {
            SCOPED_TRACE(::testing::Message() << "seed " << seed << " n " << n);
            auto boxes = boxesOf(randomSoup(n, seed));
            BuildOptions options;
            expectSane(build(boxes, options), boxes, options);
        }
    }
}

TEST(BvhBuild, OptionsAreHonouredAndClamped) {
    auto boxes = boxesOf(randomSoup(3000, 7));
    for (BuildOptions options :
         {BuildOptions{2, 1, 1, 1}, BuildOptions{1000, 16, 1, 1}, BuildOptions{0, 0, 1, 1},
          BuildOptions{32, 8, 3, 1}, BuildOptions{16, 4, 0.1f, 2}}) {
        SCOPED_TRACE(::testing::Message()
                     << "bins " << options.bins << " leaf " << options.maxLeafSize);
        Bvh bvh = build(boxes, options);
        expectSane(bvh, boxes, options);
    }
}

TEST(BvhBuild, LargeBuildUsesParallelPathsAndIsDeterministic) {
    auto boxes = boxesOf(randomSoup(150000, 11));
    Bvh a = build(boxes), b = build(boxes);
    expectSane(a, boxes, {});
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_EQ(a.primOrder, b.primOrder);
    EXPECT_EQ(0, std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(a.nodes[0])));
}

// Subtree tasks, parallel binning and the parallel partition change no bit of the tree: one
// thread and four (whatever the machine has) build the same one.
TEST(BvhBuild, OneThreadAndFourBuildTheSameTree) {
    auto tris = randomSoup(200000, 13);
    tris[100].v0.x = std::numeric_limits<float>::quiet_NaN();
    for (std::size_t i = 0; i < tris.size(); i += 50) tris[i] = tris[0];  // coincident centroids
    Bvh one, four;
    ThreadArena(1).run([&] { one = buildTriangles(tris); });
    ThreadArena(4).run([&] { four = buildTriangles(tris); });
    EXPECT_EQ(one.primOrder, four.primOrder);
    ASSERT_EQ(one.nodes.size(), four.nodes.size());
    EXPECT_EQ(0, std::memcmp(one.nodes.data(), four.nodes.data(),
                             one.nodes.size() * sizeof(one.nodes[0])));
}

TEST(BvhBuild, TrianglesAndTheirBoxesGiveTheSameTree) {
    // buildTriangles computes boxes its own (vector) way; it must agree with build() on them.
    auto tris = randomSoup(20000, 5);
    tris[17].v1.y = std::numeric_limits<float>::quiet_NaN();  // sanitised the same way too
    tris[18].v2.x = std::numeric_limits<float>::infinity();
    std::vector<Aabb> boxes;
    for (const Triangle& t : tris) boxes.push_back(bounds(t));
    boxes[17] = Aabb{Vec3(std::numeric_limits<float>::quiet_NaN()), Vec3(0.0f)};
    Bvh a = buildTriangles(tris), b = build(boxes);
    EXPECT_EQ(a.primOrder, b.primOrder);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_EQ(0, std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(a.nodes[0])));
}

TEST(BvhBuild, CoincidentCentroidsStillGiveSmallLeaves) {
    // Identical boxes leave the SAH nothing to bin; the builder must split by index instead.
    std::vector<Aabb> boxes(1000, Aabb{Vec3(-1.0f), Vec3(1.0f)});
    BuildOptions options;
    Bvh bvh = build(boxes, options);
    expectSane(bvh, boxes, options);
    BvhStats s = computeStats(bvh, options);
    EXPECT_EQ(s.maxLeafSize, 4u);
    EXPECT_LE(s.maxDepth, 10u);  // balanced: ceil(log2(250)) + 1
}

TEST(BvhBuild, DepthStaysBoundedOnExponentialSpacing) {
    // With spacing factor 3 and two bins, the only split the binning offers peels off the
    // farthest triangle: 70 levels unguarded. The guard must stop at PN_BVH_MAX_DEPTH exactly,
    // and still put one triangle per leaf.
    std::vector<Triangle> tris;
    float x = 1.0f;
    for (int i = 0; i < 70; ++i, x *= 3.0f) tris.push_back({{x, 0, 0}, {x, 1, 0}, {x, 0, 1}});
    auto boxes = boxesOf(tris);
    BuildOptions options;
    options.bins = 2;
    options.maxLeafSize = 1;
    Bvh bvh = build(boxes, options);
    expectSane(bvh, boxes, options);
    EXPECT_EQ(computeStats(bvh, options).maxDepth, std::size_t(PN_BVH_MAX_DEPTH));
    options.bins = 16;

    // Milder spacing over many more triangles, default bins: deep (~40) but bounded.
    tris.clear();
    x = 1.0f;
    for (int i = 0; i < 1000; ++i, x *= 1.09f) tris.push_back({{x, 0, 0}, {x, 1, 0}, {x, 0, 1}});
    boxes = boxesOf(tris);
    for (int leaf : {1, 4}) {
        options.maxLeafSize = leaf;
        expectSane(build(boxes, options), boxes, options);
    }
}

TEST(BvhBuild, NonFiniteBoundsDoNotBreakTheBuild) {
    constexpr float nan = std::numeric_limits<float>::quiet_NaN();
    constexpr float inf = std::numeric_limits<float>::infinity();
    auto boxes = boxesOf(randomSoup(500, 3));
    for (std::size_t i = 0; i < boxes.size(); i += 7) boxes[i].lo.x = nan;
    for (std::size_t i = 3; i < boxes.size(); i += 11) boxes[i].hi.y = inf;
    boxes.push_back(Aabb{});  // empty box
    boxes.push_back({Vec3(nan), Vec3(nan)});
    boxes.push_back({Vec3(-inf), Vec3(inf)});
    Bvh bvh = build(boxes);
    expectSane(bvh, boxes, {});
    std::vector<Aabb> allBad(50, Aabb{Vec3(nan), Vec3(inf)});
    expectSane(build(allBad), allBad, {});
}

TEST(BvhBuild, HugeCoordinatesDoNotBreakTheSah) {
    // Areas overflow to inf, so every SAH cost is inf or NaN; the build must still split.
    std::vector<Aabb> boxes;
    for (int i = 0; i < 200; ++i) {
        float s = (i % 2 ? 1.0f : -1.0f) * 3e38f * float(i + 1) / 200.0f;
        boxes.push_back({{s, -3e38f, -3e38f}, {s, 3e38f, 3e38f}});
    }
    expectSane(build(boxes), boxes, {});
}

TEST(BvhBuild, SahBeatsMedianSplit) {
    for (std::uint32_t seed : {5u, 6u}) {
        // A soup with clusters and empty space, like real scenes; uniform soups favour medians.
        auto tris = randomSoup(4000, seed);
        for (std::size_t i = 0; i < tris.size(); i += 3) {
            Vec3 shift(3.0f, 0.0f, 0.0f);
            tris[i] = {tris[i].v0 * 0.2f + shift, tris[i].v1 * 0.2f + shift,
                       tris[i].v2 * 0.2f + shift};
        }
        auto boxes = boxesOf(tris);
        BuildOptions options;
        double sah = computeStats(build(boxes, options), options).sahCost;
        Bvh median = test::buildMedianSplit(boxes, options.maxLeafSize);
        ASSERT_NO_THROW(validate(median, boxes));
        double baseline = computeStats(median, options).sahCost;
        EXPECT_LT(sah, baseline * 0.95) << "binned SAH " << sah << ", median " << baseline;
        EXPECT_GT(sah, 1.0);  // a cost below one leaf test per ray would mean a broken metric
    }
}

TEST(BvhBuild, StatsOfAHandMadeTree) {
    // Root [0,2]^3 with two unit-cube leaves of 1 and 2 primitives.
    Bvh bvh;
    bvh.nodes = {{Vec3(0.0f), 2, Vec3(2.0f), 0},
                 {Vec3(0.0f), 0, Vec3(1.0f), 1},
                 {Vec3(1.0f), 1, Vec3(2.0f), 2}};
    bvh.primOrder = {0, 1, 2};
    BuildOptions options{16, 4, 2.0f, 1.0f};
    BvhStats s = computeStats(bvh, options);
    EXPECT_EQ(s.leaves, 2u);
    EXPECT_EQ(s.maxDepth, 2u);
    EXPECT_EQ(s.maxLeafSize, 2u);
    EXPECT_DOUBLE_EQ(s.avgLeafSize, 1.5);
    EXPECT_DOUBLE_EQ(s.sahCost, (12.0 * 2.0 + 3.0 * 1 + 3.0 * 2) / 12.0);
}

TEST(BvhValidate, CatchesBrokenTrees) {
    auto boxes = boxesOf(randomSoup(100, 9));
    Bvh good = build(boxes);
    Bvh shrunk = good;
    shrunk.nodes[1].boundsMax.x += 10.0f;  // child sticks out of the root
    EXPECT_THROW(validate(shrunk, boxes), Error);
    Bvh dup = good;
    dup.primOrder[0] = dup.primOrder[1];
    EXPECT_THROW(validate(dup, boxes), Error);
    Bvh badLink = good;
    badLink.nodes[0].firstOrRight = std::uint32_t(badLink.nodes.size());
    EXPECT_THROW(validate(badLink, boxes), Error);
}

}  // namespace
}  // namespace penumbra::bvh
