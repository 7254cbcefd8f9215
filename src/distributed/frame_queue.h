// Frames of a sequence handed out one at a time to whichever rank is free, so fast and slow
// devices both stay busy. Rank 0 holds the list. Its server (serve(), in a second thread while
// rank 0's main thread renders too, when MPI allows threads) answers the other ranks' requests;
// each request carries the frame the rank just finished, which rank 0 reports through onDone.
#pragma once

#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "distributed/comm.h"

namespace penumbra::distributed {

struct FrameDone {
    std::int64_t frame = 0;
    int rank = 0;
    std::uint32_t samplesPerPixel = 0;
    double seconds = 0;
};

class FrameQueue {
public:
    // frames: in the order to hand them out (read on rank 0 only). onDone: called on rank 0, one
    // call at a time, for every finished frame.
    FrameQueue(Comm& comm, std::vector<std::int64_t> frames, std::function<void(const FrameDone&)> onDone);
    ~FrameQueue();  // joins the server thread
    FrameQueue(const FrameQueue&) = delete;
    FrameQueue& operator=(const FrameQueue&) = delete;

    // Whether this rank renders frames: all but rank 0 of a job without MPI threads, whose rank
    // 0 only serves.
    bool renders() const;
    // The next frame for this rank, or nothing when all are handed out; `finished` is the frame
    // this rank just rendered, if any.
    std::optional<std::int64_t> next(const std::optional<FrameDone>& finished);
    // Rank 0: answers requests until every other rank has been told there is no more work. In
    // the server thread, or in the main thread when rank 0 does not render.
    void serve();
    // Rank 0: waits for the server thread (every other rank has its last answer).
    void finish();

private:
    std::optional<std::int64_t> take();  // locked
    void report(const FrameDone& done);  // locked

    Comm& comm_;
    std::vector<std::int64_t> frames_;
    std::size_t nextIndex_ = 0;
    std::function<void(const FrameDone&)> onDone_;
    std::mutex mutex_;
    std::thread server_;
};

}  // namespace penumbra::distributed
