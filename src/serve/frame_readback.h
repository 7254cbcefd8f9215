// The rendered frames on their way from the GPU to the encoder, without either waiting for the
// other: a ring of host-visible copies of the display buffer. The render thread copies each frame
// into a free slot inside the frame's own submission; once it has finished, the slot becomes the
// newest ready frame (replacing a ready one the encoder has not taken: that frame is dropped).
// The encoder takes the newest ready frame when it is free. With three slots one is always free.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <vector>

#include "gpu/buffer.h"

namespace penumbra::serve {

// What the encoder needs to know of a frame besides its pixels.
struct FrameMeta {
    std::uint32_t frame = 0;
    std::uint32_t width = 0, height = 0;
    float renderMs = 0;
    bool moving = false;  // the camera or the scene moved: encoded at the lower quality
    // Each browser's latest input applied before the frame: (client id, seq).
    std::vector<std::pair<std::uint64_t, std::uint32_t>> acks;
};

struct ReadbackSlot {
    gpu::Buffer pixels;  // RGBA8, width x height, rows packed
    FrameMeta meta;
    enum class State { Free, Copying, Ready, Encoding } state = State::Free;
};

class FrameReadback {
public:
    explicit FrameReadback(const gpu::Context& ctx);

    // Render thread, while recording a frame after its passes: copies the display buffer into a
    // free slot. Returns false (no copy) when the frame is too large for the ring.
    bool recordCopy(VkCommandBuffer cmd, const gpu::Buffer& display, FrameMeta meta);
    // Render thread, once that submission has finished: the copy becomes the newest ready frame,
    // with the frame's GPU time (known only now).
    void publish(float renderMs);

    // Encoder thread: the newest ready frame, waiting for one until `stop` is set and notify()
    // called; null when stopping. Give it back with release().
    ReadbackSlot* take(const std::atomic<bool>& stop);
    void release(ReadbackSlot* slot);
    void notify();  // wakes take() (to stop)

    std::uint64_t dropped() const;  // ready frames replaced before the encoder took them

private:
    const gpu::Context& ctx_;
    std::vector<ReadbackSlot> slots_;
    ReadbackSlot* copying_ = nullptr;  // render thread only
    mutable std::mutex mutex_;
    std::condition_variable ready_;
    std::uint64_t dropped_ = 0;
};

}  // namespace penumbra::serve
