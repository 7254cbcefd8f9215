#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <thread>
#include <utility>
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

TEST(Parallel, ChunksAreNeverShorterThanMinChunk) {
    ThreadArena four(4);  // splits whatever the machine has
    for (std::size_t n : {5u, 31u, 32u, 1000u, 100003u}) {
        std::atomic<std::size_t> shortest{n}, chunks{0};
        four.run([&] {
            parallelFor(n, 16, [&](std::size_t b, std::size_t e) {
                ++chunks;
                std::size_t s = shortest.load();
                while (e - b < s && !shortest.compare_exchange_weak(s, e - b)) {
                }
            });
        });
        if (n >= 1000) {
            EXPECT_GT(chunks.load(), 1u) << "n " << n;
        }
        EXPECT_GE(shortest.load(), std::min<std::size_t>(n, 16)) << "n " << n;
    }
}

// The exception's own type arrives, from one chunk among many, even when it is thrown on a
// worker thread in a loop nested in a task.
TEST(Parallel, NestedExceptionsKeepTheirType) {
    struct Custom : std::runtime_error {
        Custom() : std::runtime_error("custom") {}
    };
    TaskGroup tasks;
    EXPECT_THROW(tasks.run([&] {
                     for (int t = 0; t < 4; ++t)
                         tasks.spawn([] {
                             parallelFor(100000, 100, [](std::size_t b, std::size_t e) {
                                 if (b <= 77777 && 77777 < e) throw Custom();
                             });
                         });
                 }),
                 Custom);
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

// Chunk c is always [c * size, (c + 1) * size), whatever the threads: a reduction combined in
// chunk order is the same on one thread and on four.
TEST(Parallel, ChunksAreFixedByTheirSizeAlone) {
    for (unsigned threads : {1u, 4u}) {
        for (std::size_t n : {0u, 1u, 99u, 100u, 100003u}) {
            std::vector<std::atomic<int>> seen(n);
            std::vector<std::pair<std::size_t, std::size_t>> ranges((n + 99) / 100);
            std::size_t chunks = 0;
            ThreadArena(threads).run([&] {
                chunks = parallelChunks(n, 100, [&](std::size_t c, std::size_t b, std::size_t e) {
                    ranges[c] = {b, e};
                    for (std::size_t i = b; i < e; ++i) seen[i]++;
                });
            });
            ASSERT_EQ(chunks, ranges.size());
            for (std::size_t c = 0; c < chunks; ++c) {
                EXPECT_EQ(ranges[c].first, c * 100);
                EXPECT_EQ(ranges[c].second, std::min(n, c * 100 + 100));
            }
            for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(seen[i].load(), 1) << "n " << n << " index " << i;
        }
    }
}

TEST(Parallel, InvokeRunsBothAndRethrows) {
    std::atomic<int> ran{0};
    parallelInvoke([&] { ran += 1; }, [&] { ran += 2; });
    EXPECT_EQ(ran.load(), 3);
    EXPECT_THROW(parallelInvoke([] {}, [] { throw std::runtime_error("half failed"); }), std::runtime_error);
}

// An arena caps the threads a loop uses: one thread runs every chunk on the caller.
TEST(Parallel, OneThreadArenaRunsOnTheCaller) {
    ThreadArena one(1);
    std::atomic<bool> elsewhere{false};
    one.run([&] {
        const auto caller = std::this_thread::get_id();
        EXPECT_EQ(hardwareThreads(), 1u);
        parallelFor(100000, 10, [&](std::size_t, std::size_t) {
            if (std::this_thread::get_id() != caller) elsewhere = true;
        });
    });
    EXPECT_FALSE(elsewhere.load());
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
