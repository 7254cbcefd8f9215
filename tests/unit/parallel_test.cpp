#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "core/parallel.h"

namespace penumbra {
namespace {

TEST(Parallel, ChunksCoverTheRangeExactlyOnce) {
    for (std::size_t n : {0u, 1u, 7u, 1000u, 100003u}) {
        std::vector<std::atomic<int>> seen(n);
        parallelFor(n, 16, [&](std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) seen[i]++;
        });
        for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(seen[i].load(), 1) << "n " << n << " index " << i;
    }
}

TEST(Parallel, ExceptionsReachTheCaller) {
    EXPECT_THROW(parallelFor(1000, 1, [](std::size_t b, std::size_t) {
                     if (b > 0) throw std::runtime_error("chunk failed");
                 }),
                 std::runtime_error);
}

}  // namespace
}  // namespace penumbra
