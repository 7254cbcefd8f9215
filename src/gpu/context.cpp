#include "gpu/context.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/error.h"
#include "gpu/check.h"

namespace penumbra::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* user) {
    std::string message = data && data->pMessage ? data->pMessage : "(no message)";
    std::fprintf(stderr, "penumbra: vulkan validation: %s\n", message.c_str());
    static_cast<Context*>(user)->recordValidationMessage(std::move(message));
    return VK_FALSE;
}

bool envFlag(const char* name) {
    const char* v = std::getenv(name);
    return v && *v && std::strcmp(v, "0") != 0;
}

bool layerAvailable(const char* name) {
    std::uint32_t count = 0;
    PN_VK(vkEnumerateInstanceLayerProperties(&count, nullptr));
    std::vector<VkLayerProperties> layers(count);
    PN_VK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
    return std::any_of(layers.begin(), layers.end(),
                       [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
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

VkInstance createInstance(bool validation, const std::vector<std::string>& extraExtensions = {}) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "penumbra";
    app.pEngineName = "penumbra";
    app.apiVersion = VK_API_VERSION_1_2;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    const char* layers[] = {kValidationLayer};
    std::vector<const char*> extensions;
    for (const std::string& e : extraExtensions) extensions.push_back(e.c_str());
    if (validation) {
        info.enabledLayerCount = 1;
        info.ppEnabledLayerNames = layers;
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkInstance instance = VK_NULL_HANDLE;
    VkResult r = vkCreateInstance(&info, nullptr, &instance);
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER || r == VK_ERROR_INITIALIZATION_FAILED) return VK_NULL_HANDLE;
    PN_VK(r);
    return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
    std::uint32_t count = 0;
    PN_VK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    PN_VK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
    devices.resize(count);
    return devices;
}

bool hasDeviceExtension(VkPhysicalDevice device, const char* name) {
    std::uint32_t count = 0;
    PN_VK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    PN_VK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()));
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

const char* kNoVulkan =
    "no Vulkan driver could be loaded; install a GPU driver with Vulkan support, or Mesa's "
    "CPU driver (Debian package mesa-vulkan-drivers)";

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
    VkInstance instance = createInstance(false);
    if (!instance) {
        if (error) *error = kNoVulkan;
        return {};
    }
    std::vector<DeviceInfo> out;
    try {
        auto devices = physicalDevices(instance);
        for (std::uint32_t i = 0; i < devices.size(); ++i) out.push_back(describe(devices[i], i));
    } catch (...) {
        vkDestroyInstance(instance, nullptr);
        throw;
    }
    vkDestroyInstance(instance, nullptr);
    return out;
}

ContextResult Context::create(const ContextOptions& options) {
    std::unique_ptr<Context> ctx(new Context());
    bool validation = options.validation || envFlag("PENUMBRA_VALIDATION");
    if (validation && !layerAvailable(kValidationLayer))
        throw Error("Vulkan validation was requested but VK_LAYER_KHRONOS_validation is not "
                    "installed; install the Debian package vulkan-validationlayers");
    ctx->instance_ = createInstance(validation, options.instanceExtensions);
    if (!ctx->instance_) return {nullptr, kNoVulkan};

    if (validation) {
        VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
        info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
        info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
        info.pfnUserCallback = onValidationMessage;
        info.pUserData = ctx.get();
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(ctx->instance_, "vkCreateDebugUtilsMessengerEXT"));
        if (!create) throw Error("the Vulkan loader lacks vkCreateDebugUtilsMessengerEXT");
        PN_VK(create(ctx->instance_, &info, nullptr, &ctx->messenger_));
    }

    if (options.createSurface) ctx->surface_ = options.createSurface(ctx->instance_);

    auto devices = physicalDevices(ctx->instance_);
    std::vector<DeviceInfo> infos;
    for (std::uint32_t i = 0; i < devices.size(); ++i) infos.push_back(describe(devices[i], i));
    if (infos.empty()) return {nullptr, std::string("no Vulkan device was found; ") + kNoVulkan};

    std::string selector = options.deviceSelector;
    if (selector.empty())
        if (const char* env = std::getenv("PENUMBRA_DEVICE")) selector = env;

    int chosen = -1;
    if (!selector.empty()) {
        bool numeric = std::all_of(selector.begin(), selector.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
        for (const DeviceInfo& d : infos) {
            bool match = numeric ? std::to_string(d.index) == selector
                                 : lower(d.name).find(lower(selector)) != std::string::npos;
            if (match) {
                chosen = static_cast<int>(d.index);
                break;
            }
        }
        if (chosen < 0)
            throw UsageError("no Vulkan device matches '" + selector +
                             "'; run 'penumbra info' to list devices and pass an index or part of a name");
        if (!infos[chosen].suitable)
            throw UsageError("device " + selector + " (" + infos[chosen].name + ") " +
                             infos[chosen].unsuitableWhy + "; pick another with --device");
    } else {
        for (const DeviceInfo& d : infos)
            if (d.suitable && (chosen < 0 || typeRank(d.type) > typeRank(infos[chosen].type)))
                chosen = static_cast<int>(d.index);
        if (chosen < 0)
            return {nullptr, "no Vulkan device supports Vulkan 1.2 compute; install a newer driver "
                             "or Mesa's lavapipe (mesa-vulkan-drivers)"};
    }

    ctx->physical_ = devices[chosen];
    ctx->info_ = infos[chosen];
    ctx->queueFamily_ = computeQueueFamily(ctx->physical_, &ctx->timestampBits_);
    std::vector<const char*> deviceExtensions;
    if (ctx->surface_) {
        ctx->queueFamily_ = presentQueueFamily(ctx->physical_, ctx->surface_, &ctx->timestampBits_);
        if (ctx->queueFamily_ == UINT32_MAX)
            throw Error("device " + ctx->info_.name + " cannot present to this window (no queue with graphics, "
                        "compute and present); pick another with --device");
        deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    }
    vkGetPhysicalDeviceMemoryProperties(ctx->physical_, &ctx->memory_);

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = ctx->queueFamily_;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &features12};
    // Query, then enable only what we use (host query reset lets the timer reset from the CPU).
    VkPhysicalDeviceVulkan12Features supported12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &supported12};
    vkGetPhysicalDeviceFeatures2(ctx->physical_, &supported);
    features12.hostQueryReset = supported12.hostQueryReset;
    if (!supported12.hostQueryReset) ctx->timestampBits_ = 0;

    // Registers and spills per pipeline, where the driver can tell (asked for, never required).
    VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR executableFeatures{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
    if (hasDeviceExtension(ctx->physical_, VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME)) {
        VkPhysicalDeviceFeatures2 query{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &executableFeatures};
        vkGetPhysicalDeviceFeatures2(ctx->physical_, &query);
        if (executableFeatures.pipelineExecutableInfo) {
            deviceExtensions.push_back(VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
            executableFeatures.pNext = features.pNext;
            features.pNext = &executableFeatures;
            ctx->pipelineStatistics_ = true;
        }
    }

    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features};
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.enabledExtensionCount = static_cast<std::uint32_t>(deviceExtensions.size());
    deviceInfo.ppEnabledExtensionNames = deviceExtensions.data();
    PN_VK(vkCreateDevice(ctx->physical_, &deviceInfo, nullptr, &ctx->device_));
    vkGetDeviceQueue(ctx->device_, ctx->queueFamily_, 0, &ctx->queue_);
    return {std::move(ctx), {}};
}

Context::~Context() {
    if (device_) {
        vkDeviceWaitIdle(device_);  // nothing useful to do with a failure while tearing down
        vkDestroyDevice(device_, nullptr);
    }
    if (surface_) vkDestroySurfaceKHR(instance_, surface_, nullptr);
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(instance_, messenger_, nullptr);
    }
    if (instance_) vkDestroyInstance(instance_, nullptr);
}

std::uint32_t Context::findMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required) const {
    for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & required) == required)
            return i;
    return UINT32_MAX;
}

std::vector<std::string> Context::validationMessages() const {
    std::lock_guard lock(messagesMutex_);
    return messages_;
}

void Context::recordValidationMessage(std::string message) {
    std::lock_guard lock(messagesMutex_);
    messages_.push_back(std::move(message));
}

}  // namespace penumbra::gpu
