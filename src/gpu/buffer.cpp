#include "gpu/buffer.h"

#include <algorithm>

#include "core/error.h"
#include "gpu/check.h"
#include "gpu/commands.h"
#include "gpu/limits.h"

namespace penumbra::gpu {

Buffer::Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryKind kind) {
    size_ = std::max<VkDeviceSize>(16, (size + 15) / 16 * 16);
    // Shaders bind whole buffers: a storage buffer past the device's range would be refused by
    // validation, or silently cut short without it.
    if (usage & VK_BUFFER_USAGE_STORAGE_BUFFER_BIT)
        checkStorageBufferFits(ctx, size_, "a storage buffer",
                               "render a smaller image (--width/--height) or scene, or pick another device (--device)");
    VkDevice device = ctx.device();
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size_;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    PN_VK(vkCreateBuffer(device, &info, nullptr, &buffer));
    buffer_ = BufferHandle(device, buffer);

    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device, buffer, &req);
    VkMemoryPropertyFlags wanted = kind == MemoryKind::DeviceLocal
                                       ? VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT
                                       : VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    std::uint32_t type = UINT32_MAX;
    if (kind == MemoryKind::HostReadback)
        type = ctx.findMemoryType(req.memoryTypeBits, wanted | VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
    if (type == UINT32_MAX) type = ctx.findMemoryType(req.memoryTypeBits, wanted);
    if (type == UINT32_MAX && kind == MemoryKind::DeviceLocal) type = ctx.findMemoryType(req.memoryTypeBits, 0);
    if (type == UINT32_MAX) throw Error("the GPU offers no memory type for a buffer of " + std::to_string(size_) + " bytes");

    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = type;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    PN_VK(vkAllocateMemory(device, &alloc, nullptr, &memory));
    memory_ = MemoryHandle(device, memory);
    PN_VK(vkBindBufferMemory(device, buffer, memory, 0));
    if (kind != MemoryKind::DeviceLocal) PN_VK(vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &mapped_));
    tally_ = BufferTally(req.size);
}

Buffer::~Buffer() {
    // Unmapping is implicit in vkFreeMemory; members free memory after the buffer is destroyed
    // (declaration order: buffer_ then memory_, destroyed in reverse).
}

Buffer uploadStorageBuffer(const Context& ctx, Commands& commands, const void* data, VkDeviceSize bytes,
                           VkBufferUsageFlags extraUsage) {
    Buffer dst(ctx, bytes,
               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                   VK_BUFFER_USAGE_TRANSFER_SRC_BIT | extraUsage,
               MemoryKind::DeviceLocal);
    if (bytes == 0) return dst;
    Buffer staging(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::HostVisible);
    std::memcpy(staging.mapped(), data, bytes);
    commands.run([&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, staging.get(), dst.get(), 1, &region);
    });
    return dst;
}

void uploadToBuffer(const Context& ctx, Commands& commands, const Buffer& dst, const void* data, VkDeviceSize bytes) {
    PN_CHECK(bytes <= dst.size());
    if (bytes == 0) return;
    Buffer staging(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::HostVisible);
    std::memcpy(staging.mapped(), data, bytes);
    commands.run([&](VkCommandBuffer cmd) {
        computeBarrier(cmd);  // passes still reading the buffer finish first
        VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, staging.get(), dst.get(), 1, &region);
    });
}

void downloadBuffer(const Context& ctx, Commands& commands, const Buffer& src, void* dst, VkDeviceSize bytes) {
    if (bytes == 0) return;
    PN_CHECK(bytes <= src.size());
    Buffer staging(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::HostVisible);
    commands.run([&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, src.get(), staging.get(), 1, &region);
    });
    std::memcpy(dst, staging.mapped(), bytes);
}

}  // namespace penumbra::gpu
