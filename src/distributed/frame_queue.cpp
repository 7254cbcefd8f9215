#include "distributed/frame_queue.h"

#include <chrono>
#include <cmath>
#include <exception>

namespace penumbra::distributed {
namespace {

constexpr int kRequest = 101, kReply = 102;
constexpr std::int64_t kNone = -1;  // frame numbers are >= 0 (parseFrames)

}  // namespace

FrameQueue::FrameQueue(Comm& comm, std::vector<std::int64_t> frames, std::function<void(const FrameDone&)> onDone)
    : comm_(comm), frames_(std::move(frames)), onDone_(std::move(onDone)) {
    if (comm_.primary() && comm_.size() > 1 && renders())
        server_ = std::thread([this] {
            try {
                serve();
            } catch (const std::exception& e) {
                comm_.fail(e.what(), 1);
            }
        });
}

FrameQueue::~FrameQueue() {
    // Unwinding from a failure on rank 0: the other ranks will never finish, so do not wait for
    // the server (Comm::fail is about to end the job).
    if (server_.joinable()) {
        if (std::uncaught_exceptions() > 0) server_.detach();
        else server_.join();
    }
}

bool FrameQueue::renders() const { return !comm_.primary() || comm_.size() == 1 || comm_.canShareWithThread(); }

std::optional<std::int64_t> FrameQueue::take() {
    std::lock_guard lock(mutex_);
    if (nextIndex_ >= frames_.size()) return std::nullopt;
    return frames_[nextIndex_++];
}

void FrameQueue::report(const FrameDone& done) {
    std::lock_guard lock(mutex_);
    if (onDone_) onDone_(done);
}

std::optional<std::int64_t> FrameQueue::next(const std::optional<FrameDone>& finished) {
    if (comm_.primary()) {
        if (finished) report(*finished);
        return take();
    }
    const std::int64_t request[3] = {finished ? finished->frame : kNone, finished ? finished->samplesPerPixel : 0,
                                     finished ? std::llround(finished->seconds * 1e6) : 0};
    comm_.send(0, kRequest, request);
    const std::vector<std::int64_t> reply = comm_.receive(0, kReply);
    if (reply.size() != 1 || reply[0] == kNone) return std::nullopt;
    return reply[0];
}

void FrameQueue::serve() {
    int active = comm_.size() - 1;  // ranks not yet told that the work is done
    std::vector<std::int64_t> request;
    auto pause = std::chrono::microseconds(100);
    while (active > 0) {
        int from = 0;
        if (!comm_.tryReceive(kRequest, &from, request)) {
            std::this_thread::sleep_for(pause);
            pause = std::min(pause * 2, std::chrono::microseconds(5000));
            continue;
        }
        pause = std::chrono::microseconds(100);
        if (request.size() == 3 && request[0] != kNone)
            report(FrameDone{request[0], from, std::uint32_t(request[1]), double(request[2]) * 1e-6});
        const std::optional<std::int64_t> frame = take();
        const std::int64_t reply[1] = {frame ? *frame : kNone};
        comm_.send(from, kReply, reply);
        if (!frame) --active;
    }
}

void FrameQueue::finish() {
    if (server_.joinable()) server_.join();
}

}  // namespace penumbra::distributed
