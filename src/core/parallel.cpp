#include "core/parallel.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>

namespace penumbra {
namespace {

// [begin, end) that splits only into halves of at least `grain`, so that parallelFor keeps its
// promise on chunk sizes whatever partitioner TBB applies.
class EvenRange {
public:
    EvenRange(std::size_t begin, std::size_t end, std::size_t grain)
        : begin_(begin), end_(end), grain_(grain) {}
    EvenRange(EvenRange& other, tbb::split)
        : begin_(other.begin_ + (other.end_ - other.begin_) / 2),
          end_(other.end_),
          grain_(other.grain_) {
        other.end_ = begin_;
    }
    bool empty() const { return begin_ == end_; }
    bool is_divisible() const { return end_ - begin_ >= 2 * grain_; }
    std::size_t begin() const { return begin_; }
    std::size_t end() const { return end_; }

private:
    std::size_t begin_, end_, grain_;
};

}  // namespace

unsigned hardwareThreads() {
    return unsigned(std::max(1, tbb::this_task_arena::max_concurrency()));
}

void parallelFor(std::size_t count, std::size_t minChunk,
                 const std::function<void(std::size_t, std::size_t)>& body) {
    if (count == 0) return;
    minChunk = std::max<std::size_t>(1, minChunk);
    if (count < 2 * minChunk || hardwareThreads() == 1) {
        body(0, count);
        return;
    }
    tbb::parallel_for(EvenRange(0, count, minChunk),
                      [&](const EvenRange& r) { body(r.begin(), r.end()); });
}

std::size_t parallelChunks(std::size_t count, std::size_t chunkSize,
                           const std::function<void(std::size_t, std::size_t, std::size_t)>& body) {
    chunkSize = std::max<std::size_t>(1, chunkSize);
    const std::size_t chunks = (count + chunkSize - 1) / chunkSize;
    parallelFor(chunks, 1, [&](std::size_t lo, std::size_t hi) {
        for (std::size_t c = lo; c < hi; ++c)
            body(c, c * chunkSize, std::min(count, (c + 1) * chunkSize));
    });
    return chunks;
}

void parallelInvoke(const std::function<void()>& a, const std::function<void()>& b) {
    tbb::parallel_invoke(a, b);
}

struct ThreadArena::Arena {
    tbb::task_arena arena;
};

ThreadArena::ThreadArena(unsigned threads)
    : arena_(std::make_unique<Arena>(Arena{tbb::task_arena(int(std::max(1u, threads)))})) {}
ThreadArena::~ThreadArena() = default;

void ThreadArena::run(const std::function<void()>& work) { arena_->arena.execute(work); }

struct TaskGroup::Pool {
    tbb::task_group group;
};

TaskGroup::TaskGroup() : pool_(std::make_unique<Pool>()) {}
TaskGroup::~TaskGroup() = default;

void TaskGroup::spawn(Task task) { pool_->group.run(std::move(task)); }

void TaskGroup::run(Task root) { pool_->group.run_and_wait(std::move(root)); }

}  // namespace penumbra
