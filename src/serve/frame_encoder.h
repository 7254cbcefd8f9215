// The encoding thread: takes the newest frame the GPU has finished, encodes it as JPEG strips in
// parallel (one strip per worker) and hands the result to `deliver`. It never holds up the render
// thread: frames that arrive while it is busy replace each other (frame_readback.h), so it
// always encodes the freshest. It sends at most maxFps frames a second.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <thread>

#include "serve/frame_message.h"
#include "serve/frame_readback.h"

namespace penumbra::serve {

struct EncodeOptions {
    int threads = 4;          // strips encoded at once
    int restQuality = 85;     // JPEG quality while nothing moves
    int motionQuality = 60;   // while the camera or the scene moves
    double maxFps = 60;       // 0: as fast as frames come
};

// A frame ready to send to every browser.
struct EncodedFrame {
    FrameInfo info;
    std::uint32_t stripCount = 0;
    std::string strips;  // packStrips()
    std::vector<std::pair<std::uint64_t, std::uint32_t>> acks;  // FrameMeta::acks
    std::chrono::steady_clock::time_point encodedAt;
};

class FrameEncoder {
public:
    using Deliver = std::function<void(std::shared_ptr<const EncodedFrame>)>;
    FrameEncoder(FrameReadback& readback, const EncodeOptions& options, Deliver deliver);
    ~FrameEncoder();  // stops the thread

    // Whether a frame finishing `frameSeconds` from now would be encoded soon after: the render
    // thread copies only such frames, so the GPU does not copy frames that would be dropped.
    bool wantsFrame(double frameSeconds) const;
    double lastEncodeMs() const { return lastEncodeMs_.load(); }

private:
    void run();
    std::shared_ptr<EncodedFrame> encode(const ReadbackSlot& slot);

    FrameReadback& readback_;
    EncodeOptions options_;
    Deliver deliver_;
    std::atomic<bool> stop_{false};
    std::atomic<std::int64_t> nextDueNs_{0};  // steady_clock: when the next frame may go
    std::atomic<double> lastEncodeMs_{0};
    struct Workers;  // the encoders and the task arena, kept out of this header
    std::unique_ptr<Workers> workers_;
    std::thread thread_;
};

}  // namespace penumbra::serve
