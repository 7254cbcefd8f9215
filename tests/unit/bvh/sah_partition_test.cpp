// The parallel partition of large nodes against the serial one: same split, same order.
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "bvh/sah_binning.h"
#include "core/parallel.h"

namespace penumbra::bvh::sah {
namespace {

// Random boxes with a share of odd ones: NaN and infinite coordinates (which the builder would
// have sanitised, but partition() promises to place like binning does), flat and point boxes,
// and clusters of equal centroids.
std::vector<PrimRef> oddSoup(std::uint32_t n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<PrimRef> refs(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        Vec3 lo(u(rng), u(rng), u(rng));
        Vec3 hi = lo + Vec3(0.01f * u(rng), 0.01f * u(rng), 0.01f * u(rng));
        switch (i % 97) {
            case 3: lo.x = hi.x = nan; break;
            case 5: lo.y = nan; break;
            case 7: hi.z = inf; break;
            case 11: hi = lo; break;  // a point
            case 13: hi.y = lo.y; break;  // flat
            case 17: lo = Vec3(0.5f), hi = Vec3(0.5f); break;  // a cluster
            default: break;
        }
        refs[i].lo = simd::F4{lo.x, lo.y, lo.z, 0.0f};
        refs[i].lo[3] = std::bit_cast<float>(i);
        refs[i].hi = simd::F4{hi.x, hi.y, hi.z, 0.0f};
    }
    return refs;
}

bool sameBits(const std::vector<PrimRef>& a, const std::vector<PrimRef>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(PrimRef)) == 0;
}

TEST(SahPartition, ParallelPartitionIsTheSerialOneToTheBit) {
    ThreadArena four(4);
    const BuildOptions options;
    const SahBinning sah(options);
    // A sub-range that does not start at 0, as deeper nodes do, of two chunks, of two and a
    // bit, and of several.
    const std::uint32_t begin = 7;
    for (std::uint32_t n : {begin + 2 * SahBinning::kMinChunk, begin + 2 * SahBinning::kMinChunk + 1,
                            100003u}) {
        for (std::uint32_t seed : {1u, 2u}) {
            SCOPED_TRACE(::testing::Message() << "n " << n << " seed " << seed);
            const std::vector<PrimRef> src = oddSoup(n, seed);
            const Range range = gather(src.data(), begin, n);
            const Split serial = sah.find(src.data(), range, 1);
            ASSERT_GE(serial.axis, 0);
            EXPECT_TRUE(serial.chunkLeft.empty());
            Split parallel;
            four.run([&] { parallel = sah.find(src.data(), range, 4); });
            ASSERT_GT(parallel.chunkLeft.size(), 1u);  // the parallel path was taken
            EXPECT_EQ(parallel.axis, serial.axis);
            EXPECT_EQ(parallel.bin, serial.bin);
            EXPECT_EQ(parallel.left.size(), serial.left.size());

            std::vector<PrimRef> a(n), b(n);
            const std::uint32_t leftA = sah.partition(src.data(), a.data(), range, serial);
            std::uint32_t leftB = 0;
            four.run([&] { leftB = sah.partition(src.data(), b.data(), range, parallel); });
            EXPECT_EQ(leftA, serial.left.size());
            EXPECT_EQ(leftB, leftA);
            EXPECT_TRUE(sameBits(a, b));
            // Every primitive lands once, on the side its centroid's bin says.
            std::vector<int> seen(n, 0);
            for (std::uint32_t i = begin; i < n; ++i) ++seen[b[i].id()];
            for (std::uint32_t i = begin; i < n; ++i) ASSERT_EQ(seen[i], 1) << "primitive " << i;
        }
    }
}

// Counts that do not match what the pass finds (as if binning had decided a primitive
// differently) must not corrupt the output: the serial pass redoes the range.
TEST(SahPartition, DisagreeingChunkCountsFallBackToTheSerialPass) {
    ThreadArena four(4);
    const SahBinning sah(BuildOptions{});
    const std::uint32_t n = 3 * SahBinning::kMinChunk;
    const std::vector<PrimRef> src = oddSoup(n, 3);
    const Range range = gather(src.data(), 0, n);
    Split split;
    four.run([&] { split = sah.find(src.data(), range, 4); });
    ASSERT_GT(split.chunkLeft.size(), 1u);
    Split serial = split;
    serial.chunkLeft.clear();
    std::vector<PrimRef> a(n), b(n);
    const std::uint32_t leftA = sah.partition(src.data(), a.data(), range, serial);
    ASSERT_GT(split.chunkLeft[0], 0u);
    split.chunkLeft[0] -= 1;
    split.chunkLeft[1] += 1;
    std::uint32_t leftB = 0;
    four.run([&] { leftB = sah.partition(src.data(), b.data(), range, split); });
    EXPECT_EQ(leftB, leftA);
    EXPECT_TRUE(sameBits(a, b));
}

}  // namespace
}  // namespace penumbra::bvh::sah
