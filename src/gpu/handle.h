// Move-only owner of one Vulkan handle, destroyed with the function it was made for, and counted
// in vulkanTally() while it lives.
#pragma once

#include <vulkan/vulkan.h>

#include <utility>

#include "gpu/tally.h"

namespace penumbra::gpu {

template <typename T, void (*Destroy)(VkDevice, T, const VkAllocationCallbacks*)>
class DeviceHandle {
public:
    DeviceHandle() = default;
    DeviceHandle(VkDevice device, T handle) : device_(device), handle_(handle) {
        if (handle_ != VK_NULL_HANDLE) tally::deviceObjectCreated();
    }
    DeviceHandle(DeviceHandle&& o) noexcept
        : device_(o.device_), handle_(std::exchange(o.handle_, VK_NULL_HANDLE)) {}
    DeviceHandle& operator=(DeviceHandle&& o) noexcept {
        if (this != &o) {
            reset();
            device_ = o.device_;
            handle_ = std::exchange(o.handle_, VK_NULL_HANDLE);
        }
        return *this;
    }
    DeviceHandle(const DeviceHandle&) = delete;
    DeviceHandle& operator=(const DeviceHandle&) = delete;
    ~DeviceHandle() { reset(); }

    void reset() {
        if (handle_ != VK_NULL_HANDLE) {
            Destroy(device_, handle_, nullptr);
            tally::deviceObjectDestroyed();
        }
        handle_ = VK_NULL_HANDLE;
    }
    T get() const { return handle_; }
    explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    T handle_ = VK_NULL_HANDLE;
};

using ShaderModule = DeviceHandle<VkShaderModule, vkDestroyShaderModule>;
using DescriptorSetLayout = DeviceHandle<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using PipelineLayout = DeviceHandle<VkPipelineLayout, vkDestroyPipelineLayout>;
using Pipeline = DeviceHandle<VkPipeline, vkDestroyPipeline>;
using DescriptorPool = DeviceHandle<VkDescriptorPool, vkDestroyDescriptorPool>;
using BufferHandle = DeviceHandle<VkBuffer, vkDestroyBuffer>;
using MemoryHandle = DeviceHandle<VkDeviceMemory, vkFreeMemory>;
using QueryPool = DeviceHandle<VkQueryPool, vkDestroyQueryPool>;
using Fence = DeviceHandle<VkFence, vkDestroyFence>;
using CommandPool = DeviceHandle<VkCommandPool, vkDestroyCommandPool>;

}  // namespace penumbra::gpu
