// The encoding thread: takes the newest frame the GPU has finished, encodes it as JPEG strips in
// parallel (one strip per worker) and hands the result to `deliver`. It never holds up the render
// thread: frames that arrive while it is busy replace each other (frame_readback.h), so it
// always encodes the freshest. Which frames reach it is the pacer's choice (frame_pacer.h).
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
    int motionQuality = 50;   // while the camera or the scene moves (docs/SERVE.md: bandwidth)
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

    double lastEncodeMs() const { return lastEncodeMs_.load(); }

private:
    void run();
    std::shared_ptr<EncodedFrame> encode(const ReadbackSlot& slot);

    FrameReadback& readback_;
    EncodeOptions options_;
    Deliver deliver_;
    std::atomic<bool> stop_{false};
    std::atomic<double> lastEncodeMs_{0};
    struct Workers;  // the encoders and the task arena, kept out of this header
    std::unique_ptr<Workers> workers_;
    std::thread thread_;
};

}  // namespace penumbra::serve
