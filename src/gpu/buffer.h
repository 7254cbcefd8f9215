// GPU buffers: device-local ones filled through a staging copy, and host-visible ones that stay
// mapped (uniforms, read-back).
#pragma once

#include <cstring>
#include <span>
#include <vector>

#include "gpu/context.h"
#include "gpu/handle.h"
#include "gpu/tally.h"

namespace penumbra::gpu {

class Commands;

// HostReadback: host-visible memory the CPU reads often (frames streamed to a browser): cached
// where the device offers it, since reads from uncached, write-combined memory are many times
// slower; coherent like HostVisible.
enum class MemoryKind { DeviceLocal, HostVisible, HostReadback };

class Buffer {
public:
    Buffer() = default;
    // Sizes are rounded up to 16 bytes: Vulkan forbids empty buffers, and empty scene arrays
    // (a scene without lights) still need something bound.
    Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryKind kind);
    Buffer(Buffer&&) noexcept = default;
    Buffer& operator=(Buffer&&) noexcept = default;
    ~Buffer();

    VkBuffer get() const { return buffer_.get(); }
    VkDeviceSize size() const { return size_; }
    void* mapped() const { return mapped_; }  // null unless HostVisible

private:
    BufferHandle buffer_;
    MemoryHandle memory_;
    BufferTally tally_;  // counts this buffer in vulkanTally() while it lives
    VkDeviceSize size_ = 0;
    void* mapped_ = nullptr;
};

// A device-local storage buffer holding `bytes`, filled through a staging buffer.
Buffer uploadStorageBuffer(const Context& ctx, Commands& commands, const void* data, VkDeviceSize bytes,
                           VkBufferUsageFlags extraUsage = 0);

template <typename T>
Buffer uploadStorageBuffer(const Context& ctx, Commands& commands, std::span<const T> items) {
    return uploadStorageBuffer(ctx, commands, items.data(), items.size_bytes());
}

// Copies `bytes` from the host to the start of an existing buffer (its descriptors stay valid),
// after the work submitted before has finished with it.
void uploadToBuffer(const Context& ctx, Commands& commands, const Buffer& dst, const void* data, VkDeviceSize bytes);

template <typename T>
void uploadToBuffer(const Context& ctx, Commands& commands, const Buffer& dst, std::span<const T> items) {
    uploadToBuffer(ctx, commands, dst, items.data(), items.size_bytes());
}

// Copies a device buffer's first `bytes` back to the host.
void downloadBuffer(const Context& ctx, Commands& commands, const Buffer& src, void* dst, VkDeviceSize bytes);

template <typename T>
std::vector<T> downloadBuffer(const Context& ctx, Commands& commands, const Buffer& src, std::size_t count) {
    std::vector<T> out(count);
    downloadBuffer(ctx, commands, src, out.data(), count * sizeof(T));
    return out;
}

}  // namespace penumbra::gpu
