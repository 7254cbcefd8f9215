// The Vulkan instance, the chosen physical device, its logical device and one compute queue.
#pragma once

#include <vulkan/vulkan.h>

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace penumbra::gpu {

struct DeviceInfo {
    std::uint32_t index = 0;
    std::string name;
    VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
    std::uint32_t apiVersion = 0;
    std::string driverInfo;
    bool suitable = false;    // Vulkan 1.2, a compute queue, the features we use
    std::string unsuitableWhy;
    VkPhysicalDeviceLimits limits{};
    std::uint64_t deviceLocalBytes = 0;
};

const char* deviceTypeName(VkPhysicalDeviceType type);
std::string versionString(std::uint32_t apiVersion);

struct ContextOptions {
    // "" picks the best device (discrete > integrated > virtual > CPU). A number picks that
    // index from `penumbra info`; any other text picks the first device whose name contains it
    // (case-insensitive), so "llvmpipe" picks lavapipe. PENUMBRA_DEVICE supplies a default.
    std::string deviceSelector;
    // Enables VK_LAYER_KHRONOS_validation and records every warning and error it reports.
    // PENUMBRA_VALIDATION=1 turns it on too.
    bool validation = false;
    // Presentation (the viewer): extra instance extensions, and a function that makes the
    // window's surface once the instance exists. The device then needs one queue family with
    // graphics, compute and present support, and VK_KHR_swapchain.
    std::vector<std::string> instanceExtensions;
    std::function<VkSurfaceKHR(VkInstance)> createSurface;
};

class Context;

// Creating a context can fail for reasons that are not bugs (no Vulkan driver, no device):
// those come back as a message so tests can skip cleanly; real errors still throw.
struct ContextResult {
    std::unique_ptr<Context> context;
    std::string error;  // set when context is null
};

class Context {
public:
    static ContextResult create(const ContextOptions& options);
    // Lists the devices without creating a logical device (for `penumbra info`).
    static std::vector<DeviceInfo> listDevices(std::string* error);

    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physicalDevice() const { return physical_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    std::uint32_t queueFamily() const { return queueFamily_; }
    const DeviceInfo& info() const { return info_; }
    double timestampPeriodNs() const { return info_.limits.timestampPeriod; }
    bool timestampsSupported() const { return timestampBits_ > 0; }
    VkSurfaceKHR surface() const { return surface_; }  // null unless ContextOptions::createSurface

    // Finds a memory type with all `required` flags among those allowed by `typeBits`.
    std::uint32_t findMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required) const;

    // VK_KHR_pipeline_executable_properties is on: pipelines can report registers and spills.
    bool pipelineStatisticsSupported() const { return pipelineStatistics_; }

    bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }
    // Messages the validation layer reported so far (tests fail if any).
    std::vector<std::string> validationMessages() const;
    void recordValidationMessage(std::string message);

private:
    Context() = default;

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    std::uint32_t queueFamily_ = 0;
    std::uint32_t timestampBits_ = 0;
    bool pipelineStatistics_ = false;
    DeviceInfo info_;
    VkPhysicalDeviceMemoryProperties memory_{};
    mutable std::mutex messagesMutex_;
    std::vector<std::string> messages_;
};

}  // namespace penumbra::gpu
