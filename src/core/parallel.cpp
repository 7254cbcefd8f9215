#include "core/parallel.h"

#include <sched.h>

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace penumbra {

// The CPUs this process may run on (taskset, container limits), not the machine's total:
// oversubscribing a 2-core allowance with 16 threads makes parallel builds slower, not faster.
unsigned hardwareThreads() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) == 0) return std::max(1, CPU_COUNT(&set));
    return std::max(1u, std::thread::hardware_concurrency());
}

void parallelFor(std::size_t count, std::size_t minChunk,
                 const std::function<void(std::size_t, std::size_t)>& body) {
    if (count == 0) return;
    minChunk = std::max<std::size_t>(1, minChunk);
    std::size_t threads = std::min<std::size_t>(hardwareThreads(), (count + minChunk - 1) / minChunk);
    if (threads <= 1) {
        body(0, count);
        return;
    }
    std::size_t chunk = (count + threads - 1) / threads;
    std::exception_ptr failure;
    std::mutex failureMutex;
    std::vector<std::thread> workers;
    workers.reserve(threads - 1);
    auto run = [&](std::size_t begin, std::size_t end) {
        try {
            body(begin, end);
        } catch (...) {
            std::lock_guard lock(failureMutex);
            if (!failure) failure = std::current_exception();
        }
    };
    for (std::size_t t = 1; t < threads; ++t) {
        std::size_t begin = t * chunk, end = std::min(count, begin + chunk);
        if (begin < end) workers.emplace_back(run, begin, end);
    }
    run(0, std::min(count, chunk));
    for (auto& w : workers) w.join();
    if (failure) std::rethrow_exception(failure);
}

void TaskGroup::spawn(Task task) {
    std::lock_guard lock(mutex_);
    if (failure_) return;
    waiting_.push_back(std::move(task));
    ++unfinished_;
    changed_.notify_one();
}

void TaskGroup::work() {
    std::unique_lock lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return !waiting_.empty() || unfinished_ == 0; });
        if (waiting_.empty()) return;  // everything finished
        Task task = std::move(waiting_.front());
        waiting_.pop_front();
        lock.unlock();
        try {
            task();
        } catch (...) {
            lock.lock();
            if (!failure_) failure_ = std::current_exception();
            unfinished_ -= waiting_.size();
            waiting_.clear();
            lock.unlock();
        }
        lock.lock();
        if (--unfinished_ == 0) changed_.notify_all();
    }
}

void TaskGroup::run(Task root) {
    {
        std::lock_guard lock(mutex_);
        failure_ = nullptr;
        waiting_.push_back(std::move(root));
        unfinished_ = 1;
    }
    std::vector<std::thread> helpers;
    for (unsigned t = 1; t < hardwareThreads(); ++t) helpers.emplace_back([this] { work(); });
    work();
    for (auto& h : helpers) h.join();
    if (failure_) std::rethrow_exception(failure_);
}

}  // namespace penumbra
