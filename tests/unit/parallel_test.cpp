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

// A binary recursion spawning its right halves: every leaf index is reached exactly once.
void visit(TaskGroup& tasks, std::vector<std::atomic<int>>& seen, std::size_t begin, std::size_t end) {
    while (end - begin > 1) {
        std::size_t mid = begin + (end - begin) / 2;
        tasks.spawn([&tasks, &seen, mid, end] { visit(tasks, seen, mid, end); });
        end = mid;
    }
    seen[begin]++;
}

TEST(TaskGroup, SpawnedTasksRunExactlyOnceBeforeRunReturns) {
    for (std::size_t n : {1u, 2u, 1000u, 4097u}) {
        std::vector<std::atomic<int>> seen(n);
        TaskGroup tasks;
        tasks.run([&] { visit(tasks, seen, 0, n); });
        for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(seen[i].load(), 1) << "n " << n << " index " << i;
    }
}

TEST(TaskGroup, ExceptionsReachTheCallerAndTheGroupIsReusable) {
    TaskGroup tasks;
    EXPECT_THROW(tasks.run([&] {
                     for (int i = 0; i < 100; ++i)
                         tasks.spawn([i] {
                             if (i == 37) throw std::runtime_error("task failed");
                         });
                 }),
                 std::runtime_error);
    std::atomic<int> ran{0};
    tasks.run([&] {
        for (int i = 0; i < 10; ++i) tasks.spawn([&] { ran++; });
    });
    EXPECT_EQ(ran.load(), 10);
}

}  // namespace
}  // namespace penumbra
