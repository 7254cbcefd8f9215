// A Vulkan device to work with: the chosen physical device, its logical device and one compute
// queue, on the process's shared instance (gpu/instance.h), with its own validation messenger.
#pragma once

#include <vulkan/vulkan.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gpu/instance.h"
#include "gpu/validation.h"

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
    // Whether validation messages are also printed to stderr (tests that provoke them on purpose
    // turn this off).
    bool printValidation = true;
    // Presentation (the viewer): extra instance extensions, and a function that makes the
    // window's surface once the instance exists. The device then needs one queue family with
    // graphics, compute and present support, and VK_KHR_swapchain.
    std::vector<std::string> instanceExtensions;
    std::function<VkSurfaceKHR(VkInstance)> createSurface;
};

class Context;

// Creating a context can fail for reasons that are not bugs (no Vulkan driver, no device):
// those come back as a message so tests can skip cleanly; real errors still throw, among them
// any failure after an earlier context in this process worked (a driver cannot have vanished).
struct ContextResult {
    std::unique_ptr<Context> context;
    std::string error;  // set when context is null
};

class Context {
public:
    static ContextResult create(const ContextOptions& options);
    // Lists the devices without creating a logical device (for `penumbra info`), on the same
    // shared instance as contexts without validation.
    static std::vector<DeviceInfo> listDevices(std::string* error);

    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance() const { return instance_->get(); }
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

    // The same messages, in a log that outlives the context: destroying the device reports the
    // objects still alive, and a test reads them after the context is gone.
    std::shared_ptr<const ValidationLog> validationLog() const { return log_; }

private:
    Context() = default;
    // create's last steps, once the physical device is chosen: its queue family (one that can
    // present too when there is a surface; returns the device extensions that needs), then the
    // logical device with the features and extensions Penumbra uses.
    std::vector<const char*> chooseQueueFamily();
    void createDevice(std::vector<const char*> deviceExtensions);

    std::shared_ptr<SharedInstance> instance_;
    std::shared_ptr<ValidationLog> log_ = std::make_shared<ValidationLog>();
    std::unique_ptr<Messenger> messenger_;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    std::uint32_t queueFamily_ = 0;
    std::uint32_t timestampBits_ = 0;
    bool pipelineStatistics_ = false;
    DeviceInfo info_;
    VkPhysicalDeviceMemoryProperties memory_{};
};

}  // namespace penumbra::gpu
