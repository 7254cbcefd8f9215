#include "gpu/context.h"

#include <vulkan/vk_enum_string_helper.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/error.h"
#include "gpu/check.h"
#include "gpu/tally.h"

namespace penumbra::gpu {
namespace {

bool envFlag(const char* name) {
    const char* v = std::getenv(name);
    return v && *v && std::strcmp(v, "0") != 0;
}

int typeRank(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
        default: return 0;
    }
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// Returns the compute queue family, or UINT32_MAX.
std::uint32_t computeQueueFamily(VkPhysicalDevice device, std::uint32_t* timestampBits) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (std::uint32_t i = 0; i < count; ++i) {
        if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
            if (timestampBits) *timestampBits = families[i].timestampValidBits;
            return i;
        }
    }
    return UINT32_MAX;
}

DeviceInfo describe(VkPhysicalDevice device, std::uint32_t index) {
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
    vkGetPhysicalDeviceProperties2(device, &props);
    DeviceInfo info;
    info.index = index;
    info.name = props.properties.deviceName;
    info.type = props.properties.deviceType;
    info.apiVersion = props.properties.apiVersion;
    info.driverInfo = std::string(driver.driverName) + " " + driver.driverInfo;
    info.limits = props.properties.limits;
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(device, &memory);
    for (std::uint32_t h = 0; h < memory.memoryHeapCount; ++h)
        if (memory.memoryHeaps[h].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            info.deviceLocalBytes += memory.memoryHeaps[h].size;

    info.suitable = true;
    if (info.apiVersion < VK_API_VERSION_1_2) {
        info.suitable = false;
        info.unsuitableWhy = "supports Vulkan " + versionString(info.apiVersion) + ", 1.2 is needed";
    } else if (computeQueueFamily(device, nullptr) == UINT32_MAX) {
        info.suitable = false;
        info.unsuitableWhy = "has no compute queue";
    }
    return info;
}

// A family that can draw (the UI), compute and present to `surface`, or UINT32_MAX.
std::uint32_t presentQueueFamily(VkPhysicalDevice device, VkSurfaceKHR surface, std::uint32_t* timestampBits) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    for (std::uint32_t i = 0; i < count; ++i) {
        VkBool32 present = VK_FALSE;
        PN_VK(vkGetPhysicalDeviceSurfaceSupportKHR(device, i, surface, &present));
        if ((families[i].queueFlags & needed) == needed && present) {
            if (timestampBits) *timestampBits = families[i].timestampValidBits;
            return i;
        }
    }
    return UINT32_MAX;
}

// Why the machine has no usable device, or why making one failed. Before any device worked in
// this process such failures are values (tests skip); after one did, they are bugs and throw.
std::string unavailable(const std::string& message) {
    const VulkanTally t = vulkanTally();
    if (t.devicesCreated == 0) return message;
    throw Error(message + " (after " + std::to_string(t.devicesCreated) + " Vulkan devices were created and " +
                std::to_string(t.devicesDestroyed) + " destroyed earlier in this process)");
}

struct Enumeration {
    std::vector<VkPhysicalDevice> devices;
    std::string error;  // set when enumeration failed or found nothing
};

Enumeration physicalDevices(VkInstance instance) {
    std::uint32_t count = 0;
    VkResult r = vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    if (r == VK_SUCCESS && count > 0) r = vkEnumeratePhysicalDevices(instance, &count, devices.data());
    if (r != VK_SUCCESS && r != VK_INCOMPLETE)
        return {{}, unavailable(std::string("a Vulkan driver is installed but could not reach a device "
                                            "(vkEnumeratePhysicalDevices returned ") +
                                string_VkResult(r) + "); VK_LOADER_DEBUG=error,warn,driver shows why")};
    devices.resize(count);
    if (devices.empty())
        return {{}, unavailable("the Vulkan drivers installed report no device (vkEnumeratePhysicalDevices "
                                "found none); check that the GPU is visible to this process")};
    return {devices, {}};
}

bool hasDeviceExtension(VkPhysicalDevice device, const char* name) {
    std::uint32_t count = 0;
    PN_VK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    PN_VK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()));
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

std::string deviceList(const std::vector<DeviceInfo>& infos) {
    std::string list;
    for (const DeviceInfo& d : infos) list += (list.empty() ? "" : ", ") + std::to_string(d.index) + " " + d.name;
    return list;
}

// What a failed vkCreateDevice means, for a user.
std::string deviceFailure(VkResult r, const std::string& name) {
    std::string message = "could not create a Vulkan device on " + name + " (vkCreateDevice returned " +
                          string_VkResult(r) + ")";
    switch (r) {
        case VK_ERROR_OUT_OF_HOST_MEMORY:
        case VK_ERROR_OUT_OF_DEVICE_MEMORY:
            message += "; out of memory: other programs may hold the GPU's memory";
            break;
        case VK_ERROR_TOO_MANY_OBJECTS:
            message += "; the driver allows no more devices at once";
            break;
        case VK_ERROR_INITIALIZATION_FAILED:
        case VK_ERROR_DEVICE_LOST:
            message += "; the driver could not start the device (VK_LOADER_DEBUG=error,warn,driver may say why)";
            break;
        case VK_ERROR_EXTENSION_NOT_PRESENT:
        case VK_ERROR_FEATURE_NOT_PRESENT:
            message += "; the device lacks a feature Penumbra needs; pick another with --device";
            break;
        default:
            break;
    }
    const VulkanTally t = vulkanTally();
    if (t.devicesCreated > 0)
        message += " (after " + std::to_string(t.devicesCreated) + " devices were created and " +
                   std::to_string(t.devicesDestroyed) + " destroyed earlier in this process)";
    return message;
}

// The device the user named (an index, or part of a name, as `penumbra info` lists them); an
// unknown or unsuitable one is a usage error.
int selectedDevice(const std::vector<DeviceInfo>& infos, const std::string& selector) {
    const bool numeric = std::all_of(selector.begin(), selector.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    int chosen = -1;
    for (const DeviceInfo& d : infos) {
        const bool match = numeric ? std::to_string(d.index) == selector
                                   : lower(d.name).find(lower(selector)) != std::string::npos;
        if (match) {
            chosen = static_cast<int>(d.index);
            break;
        }
    }
    if (chosen < 0)
        throw UsageError("no Vulkan device matches '" + selector + "' (devices here: " + deviceList(infos) +
                         "); pass an index or part of a name, as 'penumbra info' lists them");
    if (!infos[chosen].suitable)
        throw UsageError("device " + selector + " (" + infos[chosen].name + ") " + infos[chosen].unsuitableWhy +
                         "; pick another with --device");
    return chosen;
}

// The suitable device of the best type (a discrete GPU first); -1, with why none is, if none.
int bestDevice(const std::vector<DeviceInfo>& infos, std::string& whyNone) {
    int chosen = -1;
    for (const DeviceInfo& d : infos)
        if (d.suitable && (chosen < 0 || typeRank(d.type) > typeRank(infos[chosen].type)))
            chosen = static_cast<int>(d.index);
    if (chosen >= 0) return chosen;
    std::string why;
    for (const DeviceInfo& d : infos) why += (why.empty() ? "" : "; ") + d.name + " " + d.unsuitableWhy;
    whyNone = "no Vulkan device here supports Vulkan 1.2 compute (" + why + ")";
    return -1;
}

}  // namespace

const char* deviceTypeName(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
        default: return "other";
    }
}

std::string versionString(std::uint32_t v) {
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) +
           "." + std::to_string(VK_API_VERSION_PATCH(v));
}

std::vector<DeviceInfo> Context::listDevices(std::string* error) {
    InstanceResult instance = acquireInstance({});
    Enumeration found;
    if (instance.instance) found = physicalDevices(instance.instance->get());
    const std::string& why = instance.instance ? found.error : instance.error;
    if (!why.empty()) {
        if (error) *error = why;
        return {};
    }
    std::vector<DeviceInfo> out;
    for (std::uint32_t i = 0; i < found.devices.size(); ++i) out.push_back(describe(found.devices[i], i));
    return out;
}

ContextResult Context::create(const ContextOptions& options) {
    std::unique_ptr<Context> ctx(new Context());
    InstanceConfig config;
    config.validation = options.validation || envFlag("PENUMBRA_VALIDATION");
    config.extensions = options.instanceExtensions;
    InstanceResult instance = acquireInstance(config);
    if (!instance.instance) return {nullptr, unavailable(instance.error)};
    ctx->instance_ = std::move(instance.instance);
    if (config.validation) ctx->messenger_ = std::make_unique<Messenger>(ctx->instance_, ctx->log_, options.printValidation);

    if (options.createSurface) {
        std::lock_guard lock(ctx->instance_->childMutex());
        ctx->surface_ = options.createSurface(ctx->instance());
    }

    Enumeration found = physicalDevices(ctx->instance());
    if (!found.error.empty()) return {nullptr, found.error};
    const std::vector<VkPhysicalDevice>& devices = found.devices;
    std::vector<DeviceInfo> infos;
    for (std::uint32_t i = 0; i < devices.size(); ++i) infos.push_back(describe(devices[i], i));

    std::string selector = options.deviceSelector;
    if (selector.empty())
        if (const char* env = std::getenv("PENUMBRA_DEVICE")) selector = env;
    std::string none;
    const int chosen = selector.empty() ? bestDevice(infos, none) : selectedDevice(infos, selector);
    if (chosen < 0) return {nullptr, unavailable(none)};

    ctx->physical_ = devices[chosen];
    ctx->info_ = infos[chosen];
    ctx->createDevice(ctx->chooseQueueFamily());
    return {std::move(ctx), {}};
}

std::vector<const char*> Context::chooseQueueFamily() {
    queueFamily_ = computeQueueFamily(physical_, &timestampBits_);
    std::vector<const char*> deviceExtensions;
    if (surface_) {
        queueFamily_ = presentQueueFamily(physical_, surface_, &timestampBits_);
        if (queueFamily_ == UINT32_MAX)
            throw Error("device " + info_.name + " cannot present to this window (no queue with graphics, "
                        "compute and present); pick another with --device");
        deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    }
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
    return deviceExtensions;
}

void Context::createDevice(std::vector<const char*> deviceExtensions) {
    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily_;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &features12};
    // Query, then enable only what we use (host query reset lets the timer reset from the CPU).
    VkPhysicalDeviceVulkan12Features supported12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &supported12};
    vkGetPhysicalDeviceFeatures2(physical_, &supported);
    features12.hostQueryReset = supported12.hostQueryReset;
    if (!supported12.hostQueryReset) timestampBits_ = 0;

    // Registers and spills per pipeline, where the driver can tell (asked for, never required).
    VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR executableFeatures{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
    if (hasDeviceExtension(physical_, VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME)) {
        VkPhysicalDeviceFeatures2 query{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &executableFeatures};
        vkGetPhysicalDeviceFeatures2(physical_, &query);
        if (executableFeatures.pipelineExecutableInfo) {
            deviceExtensions.push_back(VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
            executableFeatures.pNext = features.pNext;
            features.pNext = &executableFeatures;
            pipelineStatistics_ = true;
        }
    }

    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features};
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.enabledExtensionCount = static_cast<std::uint32_t>(deviceExtensions.size());
    deviceInfo.ppEnabledExtensionNames = deviceExtensions.data();
    VkResult r = vkCreateDevice(physical_, &deviceInfo, nullptr, &device_);
    if (r != VK_SUCCESS) throw Error(deviceFailure(r, info_.name));
    tally::deviceCreated();
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
    if (messenger_) messenger_->setDevice(device_, queue_);
}

// The device goes first, while the messenger still listens: the validation layer reports the
// objects left alive when the device is destroyed. The instance stays (gpu/instance.h).
Context::~Context() {
    if (device_) {
        vkDeviceWaitIdle(device_);  // nothing useful to do with a failure while tearing down
        vkDestroyDevice(device_, nullptr);
        tally::deviceDestroyed();
    }
    if (surface_) {
        std::lock_guard lock(instance_->childMutex());
        vkDestroySurfaceKHR(instance(), surface_, nullptr);
    }
    messenger_.reset();
    instance_.reset();
}

std::uint32_t Context::findMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required) const {
    for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & required) == required)
            return i;
    return UINT32_MAX;
}

}  // namespace penumbra::gpu
