// Fork-join parallelism over index ranges and recursive tasks, on TBB's worker pool: no thread
// is started per call, and a call made while every worker is busy (a build nested in a parallel
// loader, a subtree task binning its node) runs on the caller instead of oversubscribing.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>

namespace penumbra {

// The threads parallel work may use here: the current TBB arena's concurrency, which by default
// is the CPUs this process may run on (taskset, container limits), not the machine's total.
unsigned hardwareThreads();

// Calls body(begin, end) on disjoint chunks covering [0, count) and returns when all are done.
// No chunk is shorter than minChunk unless count is; idle workers split the rest further.
// The first exception a chunk throws is rethrown on the caller; chunks not started by then are
// skipped.
void parallelFor(std::size_t count, std::size_t minChunk,
                 const std::function<void(std::size_t, std::size_t)>& body);

// Calls body(chunk, begin, end) for the chunks [c * chunkSize, min(count, (c + 1) * chunkSize)),
// in parallel. The chunks depend on chunkSize alone, never on the thread count, so per-chunk
// results combined in chunk order are the same on any machine (reductions that must be
// reproducible). Returns the number of chunks.
std::size_t parallelChunks(std::size_t count, std::size_t chunkSize,
                           const std::function<void(std::size_t, std::size_t, std::size_t)>& body);

// Runs a and b, possibly at once, and returns when both are done (two halves of a recursion).
// The first exception either throws is rethrown on the caller.
void parallelInvoke(const std::function<void()>& a, const std::function<void()>& b);

// A share of the pool: run() executes work, and the parallel calls it makes, on at most
// `threads` threads (a frame encoder that leaves the render loop its share; a test forcing
// several workers on a small machine). More threads than the machine has take turns.
class ThreadArena {
public:
    explicit ThreadArena(unsigned threads);
    ~ThreadArena();
    ThreadArena(const ThreadArena&) = delete;
    ThreadArena& operator=(const ThreadArena&) = delete;

    void run(const std::function<void()>& work);

private:
    struct Arena;  // tbb::task_arena, kept out of this header
    std::unique_ptr<Arena> arena_;
};

// Dynamic fork-join for recursive work whose shape is only known as it runs (BVH subtrees):
// run() executes a root task, tasks may spawn() more, and run() returns once every task has
// finished. A thread runs its own newest task first (depth first, warm caches) and idle threads
// steal the oldest, which in a recursion are the largest. The first exception a task throws is
// rethrown by run(); tasks that have not started by then are dropped. A group can run again.
class TaskGroup {
public:
    using Task = std::function<void()>;

    TaskGroup();
    ~TaskGroup();
    TaskGroup(const TaskGroup&) = delete;
    TaskGroup& operator=(const TaskGroup&) = delete;

    void run(Task root);
    void spawn(Task task);  // from inside a running task

private:
    struct Pool;  // tbb::task_group, kept out of this header
    std::unique_ptr<Pool> pool_;
};

}  // namespace penumbra
