#include "serve/frame_readback.h"

namespace penumbra::serve {
namespace {

constexpr std::size_t kSlots = 3;

void barrier(VkCommandBuffer cmd, VkPipelineStageFlags src, VkAccessFlags srcAccess, VkPipelineStageFlags dst,
             VkAccessFlags dstAccess) {
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    vkCmdPipelineBarrier(cmd, src, dst, 0, 1, &b, 0, nullptr, 0, nullptr);
}

}  // namespace

FrameReadback::FrameReadback(const gpu::Context& ctx) : ctx_(ctx), slots_(kSlots) {}

bool FrameReadback::recordCopy(VkCommandBuffer cmd, const gpu::Buffer& display, FrameMeta meta) {
    const VkDeviceSize bytes = VkDeviceSize(meta.width) * meta.height * 4;
    if (bytes == 0 || bytes > display.size()) return false;
    {
        std::lock_guard lock(mutex_);
        for (ReadbackSlot& s : slots_)
            if (s.state == ReadbackSlot::State::Free) {
                copying_ = &s;
                break;
            }
        if (!copying_) return false;  // cannot happen with three slots; no copy rather than a wait
        copying_->state = ReadbackSlot::State::Copying;
    }
    // Only this thread touches a Copying slot, so it may be reallocated outside the lock.
    if (copying_->pixels.size() < bytes)
        copying_->pixels = gpu::Buffer(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryKind::HostReadback);
    copying_->meta = std::move(meta);
    barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
            VK_ACCESS_TRANSFER_READ_BIT);
    const VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(cmd, display.get(), copying_->pixels.get(), 1, &region);
    barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
            VK_ACCESS_HOST_READ_BIT);
    return true;
}

void FrameReadback::publish(float renderMs) {
    if (!copying_) return;
    copying_->meta.renderMs = renderMs;
    {
        std::lock_guard lock(mutex_);
        for (ReadbackSlot& s : slots_)
            if (s.state == ReadbackSlot::State::Ready) {
                s.state = ReadbackSlot::State::Free;
                ++dropped_;
            }
        copying_->state = ReadbackSlot::State::Ready;
        copying_ = nullptr;
    }
    ready_.notify_one();
}

ReadbackSlot* FrameReadback::take(const std::atomic<bool>& stop) {
    std::unique_lock lock(mutex_);
    for (;;) {
        if (stop) return nullptr;
        for (ReadbackSlot& s : slots_)
            if (s.state == ReadbackSlot::State::Ready) {
                s.state = ReadbackSlot::State::Encoding;
                return &s;
            }
        ready_.wait(lock);
    }
}

void FrameReadback::release(ReadbackSlot* slot) {
    std::lock_guard lock(mutex_);
    slot->state = ReadbackSlot::State::Free;
}

void FrameReadback::notify() {
    { std::lock_guard lock(mutex_); }
    ready_.notify_all();
}

std::uint64_t FrameReadback::dropped() const {
    std::lock_guard lock(mutex_);
    return dropped_;
}

}  // namespace penumbra::serve
