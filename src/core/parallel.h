// Minimal fork-join parallelism over index ranges, using every hardware thread.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>

namespace penumbra {

unsigned hardwareThreads();

// Calls body(begin, end) on disjoint chunks covering [0, count), on up to hardwareThreads()
// threads; returns when all are done. Exceptions from a chunk are rethrown on the caller.
void parallelFor(std::size_t count, std::size_t minChunk,
                 const std::function<void(std::size_t, std::size_t)>& body);

// Dynamic fork-join for recursive work whose shape is only known as it runs (BVH subtrees):
// run() executes a root task on up to hardwareThreads() threads, tasks may spawn() more, and
// run() returns once every task has finished. Waiting tasks are taken oldest first, which in a
// recursion are the largest. The first exception a task throws is rethrown by run(); tasks that
// have not started by then are dropped.
class TaskGroup {
public:
    using Task = std::function<void()>;

    void run(Task root);
    void spawn(Task task);  // from inside a running task

private:
    void work();

    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<Task> waiting_;
    std::size_t unfinished_ = 0;  // waiting or running
    std::exception_ptr failure_;
};

}  // namespace penumbra
