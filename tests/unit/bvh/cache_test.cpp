// The on-disk BVH cache: reuse only for identical input, and damaged entries rebuilt, never
// trusted.
#include "bvh/cache.h"

#include <gtest/gtest.h>
#include <xxhash.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>
#include <vector>

#include "bvh_test_util.h"

namespace penumbra::bvh {
namespace {

namespace fs = std::filesystem;
using test::randomSoup;

class BvhCache : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("penumbra_bvh_cache_test_" +
                std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        settings_.enabled = true;
        settings_.directory = dir_;
        settings_.minPrimitives = 1;
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::vector<fs::path> entries() const {
        std::vector<fs::path> out;
        if (!fs::exists(dir_)) return out;
        for (const auto& e : fs::directory_iterator(dir_)) out.push_back(e.path());
        return out;
    }
    static void expectSame(const Bvh& a, const Bvh& b) {
        EXPECT_EQ(a.primOrder, b.primOrder);
        ASSERT_EQ(a.nodes.size(), b.nodes.size());
        EXPECT_EQ(0,
                  std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(a.nodes[0])));
    }
    static std::string bytesOf(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
    static void write(const fs::path& p, const std::string& bytes) {
        std::ofstream out(p, std::ios::binary | std::ios::trunc);
        out << bytes;
    }

    fs::path dir_;
    CacheSettings settings_;
};

TEST_F(BvhCache, SecondBuildOfTheSameInputIsReadBack) {
    const auto tris = randomSoup(3000, 1);
    const std::vector<Aabb> spheres = {{Vec3(0.2f), Vec3(0.4f)}};
    CachedBuild first = buildCached(tris, spheres, {}, settings_);
    EXPECT_FALSE(first.fromCache);
    ASSERT_EQ(entries().size(), 1u);
    CachedBuild second = buildCached(tris, spheres, {}, settings_);
    EXPECT_TRUE(second.fromCache);
    expectSame(first.bvh, second.bvh);
    std::vector<Aabb> boxes;
    for (const Triangle& t : tris) boxes.push_back(bounds(t));
    boxes.push_back(spheres[0]);
    expectSame(second.bvh, build(boxes));  // what buildSceneArrays built before the cache
}

TEST_F(BvhCache, ChangedGeometryOrOptionsNeverReuseAnEntry) {
    auto tris = randomSoup(3000, 2);
    const CachedBuild original = buildCached(tris, {}, {}, settings_);
    // One vertex moved by one unit in the last place.
    tris[1234].v1.x = std::nextafter(tris[1234].v1.x, 2.0f);
    const CachedBuild moved = buildCached(tris, {}, {}, settings_);
    EXPECT_FALSE(moved.fromCache);
    expectSame(moved.bvh, buildTriangles(tris));
    BuildOptions fewerBins;
    fewerBins.bins = 8;
    EXPECT_FALSE(buildCached(tris, {}, fewerBins, settings_).fromCache);
    // One primitive more (a sphere box) is different input too.
    EXPECT_FALSE(
        buildCached(tris, std::vector<Aabb>{{Vec3(0.0f), Vec3(1.0f)}}, {}, settings_).fromCache);
    EXPECT_EQ(entries().size(), 4u);
    EXPECT_TRUE(buildCached(tris, {}, {}, settings_).fromCache);
}

TEST_F(BvhCache, DamagedEntriesAreRebuiltWithAWarning) {
    const auto tris = randomSoup(3000, 3);
    const Bvh direct = buildTriangles(tris);
    buildCached(tris, {}, {}, settings_);
    ASSERT_EQ(entries().size(), 1u);
    const fs::path entry = entries()[0];
    const std::string good = bytesOf(entry);

    std::vector<std::string> damaged = {
        "",                                // empty
        good.substr(0, 40),                // shorter than the header
        good.substr(0, good.size() / 2),   // truncated payload
        good + "extra",                    // trailing bytes
        std::string(good.size(), '\x7f'),  // garbage
    };
    std::string flipped = good;
    flipped[flipped.size() / 2] ^= 0x40;  // one bit in the payload
    damaged.push_back(flipped);
    std::string hugeCounts = good;
    const std::uint64_t huge = ~std::uint64_t(0) / 8;
    std::memcpy(hugeCounts.data() + 32, &huge, sizeof huge);  // the node count field
    damaged.push_back(hugeCounts);

    for (std::size_t i = 0; i < damaged.size(); ++i) {
        write(entry, damaged[i]);
        testing::internal::CaptureStderr();
        CachedBuild b = buildCached(tris, {}, {}, settings_);
        const std::string err = testing::internal::GetCapturedStderr();
        EXPECT_FALSE(b.fromCache) << "case " << i;
        expectSame(b.bvh, direct);
        EXPECT_NE(err.find("penumbra: warning: BVH cache entry"), std::string::npos)
            << "case " << i << ": " << err;
        EXPECT_EQ(err.find('\n'), err.size() - 1) << "one line, case " << i << ": " << err;
        EXPECT_EQ(bytesOf(entry), good) << "rewritten, case " << i;
    }
}

TEST_F(BvhCache, AWellFormedEntryWithAWrongTreeIsNotTrusted) {
    const auto tris = randomSoup(3000, 4);
    buildCached(tris, {}, {}, settings_);
    const fs::path entry = entries()[0];
    std::string bytes = bytesOf(entry);
    // Point the root's right link past the end, and fix the checksum as a forger would.
    shader::BvhNode root;
    std::memcpy(&root, bytes.data() + 64, sizeof root);
    root.firstOrRight = 0xfffffff0u;
    std::memcpy(bytes.data() + 64, &root, sizeof root);
    const std::uint64_t hash = XXH3_64bits(bytes.data() + 64, bytes.size() - 64);
    std::memcpy(bytes.data() + 48, &hash, sizeof hash);
    write(entry, bytes);
    testing::internal::CaptureStderr();
    CachedBuild b = buildCached(tris, {}, {}, settings_);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_FALSE(b.fromCache);
    EXPECT_NE(err.find("invalid tree"), std::string::npos) << err;
    expectSame(b.bvh, buildTriangles(tris));
}

TEST_F(BvhCache, OldestEntriesGoWhenTheCacheIsFull) {
    settings_.maxBytes = 250 * 1024;  // room for about two entries of 3000 triangles
    for (std::uint32_t seed = 10; seed < 14; ++seed) {
        buildCached(randomSoup(3000, seed), {}, {}, settings_);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));  // distinct modification times
    }
    std::uintmax_t total = 0;
    for (const fs::path& p : entries()) total += fs::file_size(p);
    EXPECT_LE(total, settings_.maxBytes);
    EXPECT_GE(entries().size(), 1u);
    EXPECT_TRUE(
        buildCached(randomSoup(3000, 13), {}, {}, settings_).fromCache);  // the newest stays
    EXPECT_FALSE(
        buildCached(randomSoup(3000, 10), {}, {}, settings_).fromCache);  // the oldest went
}

TEST_F(BvhCache, OffOrSmallMeansNoFiles) {
    const auto tris = randomSoup(500, 5);
    CacheSettings off = settings_;
    off.enabled = false;
    EXPECT_FALSE(buildCached(tris, {}, {}, off).fromCache);
    CacheSettings small = settings_;
    small.minPrimitives = 1000;
    EXPECT_FALSE(buildCached(tris, {}, {}, small).fromCache);
    EXPECT_TRUE(entries().empty());
    // An unwritable folder is a warning, not an error.
    CacheSettings unwritable = settings_;
    unwritable.directory = "/proc/penumbra-cannot-write-here";
    testing::internal::CaptureStderr();
    CachedBuild b = buildCached(tris, {}, {}, unwritable);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_FALSE(b.fromCache);
    EXPECT_EQ(b.bvh.primOrder.size(), tris.size());
    EXPECT_NE(err.find("penumbra: warning: cannot store the BVH"), std::string::npos) << err;
}

}  // namespace
}  // namespace penumbra::bvh
