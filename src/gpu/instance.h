// One VkInstance per process and configuration, shared by every Context made with that
// configuration and kept until the process exits. Contexts create and destroy only their own
// device, debug messenger and surface. Creating and destroying instances over and over in one
// process is what some drivers handle worst (NVIDIA refused new contexts after about 30 cycles,
// issue 16), and an instance is slow to make anyway.
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace penumbra::gpu {

struct InstanceConfig {
    bool validation = false;              // VK_LAYER_KHRONOS_validation and VK_EXT_debug_utils
    std::vector<std::string> extensions;  // more instance extensions (a window's surface)
};

// Owns a VkInstance; destroys it when the last owner lets go.
class SharedInstance {
public:
    SharedInstance(VkInstance instance, InstanceConfig config);
    ~SharedInstance();
    SharedInstance(const SharedInstance&) = delete;
    SharedInstance& operator=(const SharedInstance&) = delete;

    VkInstance get() const { return instance_; }
    const InstanceConfig& config() const { return config_; }
    // Held while creating or destroying the instance's children (messengers, surfaces), which
    // Vulkan asks the application to serialise.
    std::mutex& childMutex() const { return childMutex_; }

private:
    VkInstance instance_;
    InstanceConfig config_;
    mutable std::mutex childMutex_;
};

struct InstanceResult {
    std::shared_ptr<SharedInstance> instance;
    std::string error;  // set when instance is null: no usable Vulkan on this machine
};

// The process's instance for `config`, made on first use. A failure that means "this machine has
// no usable Vulkan" (no driver, a driver that cannot start) comes back as a message while no
// instance was ever made in this process; any other failure, or one after earlier successes,
// throws an Error naming the call, the VkResult and what to do. Thread-safe.
//
// PENUMBRA_INSTANCE_PER_CONTEXT=1 restores the old behaviour for diagnosis: every call makes a
// new instance, destroyed with its last owner.
InstanceResult acquireInstance(const InstanceConfig& config);

// Whether PENUMBRA_INSTANCE_PER_CONTEXT asks for one instance per context.
bool instancePerContext();

}  // namespace penumbra::gpu
