#include "gpu/instance.h"

#include <vulkan/vk_enum_string_helper.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include <dlfcn.h>
#include <link.h>

#include "core/error.h"
#include "gpu/check.h"
#include "gpu/tally.h"

namespace penumbra::gpu {
namespace {

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PN_LEAK_CHECKED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define PN_LEAK_CHECKED 1
#endif

// Under LeakSanitizer (the sanitizer job): keeps every shared library loaded so far mapped until
// exit. The loader unloads the driver and the layers in vkDestroyInstance; what they kept until
// then is reported at exit from an `<unknown module>`, which no by-library suppression in
// .ci/lsan.supp can match. Pinned, the reports name the library. Elsewhere it does nothing.
void pinLoadedLibraries() {
#ifdef PN_LEAK_CHECKED
    std::vector<std::string> names;
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void* out) {
            if (info->dlpi_name && info->dlpi_name[0])
                static_cast<std::vector<std::string>*>(out)->push_back(info->dlpi_name);
            return 0;
        },
        &names);
    for (const std::string& name : names) dlopen(name.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);  // kept
#endif
}

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// Messages from vkCreateInstance and vkDestroyInstance themselves, which no Context's messenger
// can see: printed with the prefix every validation message has.
VKAPI_ATTR VkBool32 VKAPI_CALL onInstanceMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                 VkDebugUtilsMessageTypeFlagsEXT,
                                                 const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    std::fprintf(stderr, "penumbra: vulkan validation: (instance) %s\n",
                 data && data->pMessage ? data->pMessage : "(no message)");
    return VK_FALSE;
}

std::vector<std::string> availableExtensions(const char* layer) {
    std::uint32_t count = 0;
    if (vkEnumerateInstanceExtensionProperties(layer, &count, nullptr) != VK_SUCCESS) return {};
    std::vector<VkExtensionProperties> props(count);
    if (vkEnumerateInstanceExtensionProperties(layer, &count, props.data()) != VK_SUCCESS) return {};
    std::vector<std::string> names;
    for (std::uint32_t i = 0; i < count; ++i) names.push_back(props[i].extensionName);
    return names;
}

bool layerAvailable(const char* name) {
    std::uint32_t count = 0;
    if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) return false;
    std::vector<VkLayerProperties> layers(count);
    if (vkEnumerateInstanceLayerProperties(&count, layers.data()) != VK_SUCCESS) return false;
    return std::any_of(layers.begin(), layers.begin() + count,
                       [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

std::string missingExtensions(const std::vector<const char*>& wanted, bool validation) {
    std::vector<std::string> have = availableExtensions(nullptr);
    if (validation) {
        std::vector<std::string> layer = availableExtensions(kValidationLayer);
        have.insert(have.end(), layer.begin(), layer.end());
    }
    std::string missing;
    for (const char* e : wanted)
        if (std::find(have.begin(), have.end(), e) == have.end()) missing += (missing.empty() ? "" : ", ") + std::string(e);
    return missing.empty() ? "(none reported missing)" : missing;
}

// What to tell the user about a failed vkCreateInstance. `unavailable` is set for the failures
// that mean "no usable Vulkan here" rather than a bug.
std::string describeFailure(VkResult r, const std::vector<const char*>& extensions, bool validation,
                            std::uint64_t earlier, bool* unavailable) {
    const std::string call = std::string("vkCreateInstance returned ") + string_VkResult(r);
    *unavailable = false;
    if (earlier > 0)
        return call + " after this process had created " + std::to_string(earlier) +
               " Vulkan instances, so a driver is present: it refused one more (a driver limit or leak); "
               "VK_LOADER_DEBUG=error,warn,driver shows the loader's reason";
    switch (r) {
        case VK_ERROR_INCOMPATIBLE_DRIVER:
            *unavailable = true;
            return "no Vulkan driver could be loaded (" + call +
                   "); install a GPU driver with Vulkan support, or Mesa's CPU driver (Debian package "
                   "mesa-vulkan-drivers); VK_LOADER_DEBUG=driver shows where the loader looked";
        case VK_ERROR_INITIALIZATION_FAILED:
            *unavailable = true;
            return "a Vulkan driver was found but failed to start (" + call +
                   "); VK_LOADER_DEBUG=error,warn,driver shows which driver and why";
        case VK_ERROR_LAYER_NOT_PRESENT:
            return "the Vulkan validation layer is missing (" + call +
                   "); install the Debian package vulkan-validationlayers, or point VK_LAYER_PATH at the "
                   "folder of its VkLayer_khronos_validation.json";
        case VK_ERROR_EXTENSION_NOT_PRESENT:
            return "the Vulkan loader lacks instance extensions " + missingExtensions(extensions, validation) +
                   " (" + call + "); a window needs a driver that can present to this display";
        case VK_ERROR_OUT_OF_HOST_MEMORY:
        case VK_ERROR_OUT_OF_DEVICE_MEMORY:
            return "out of memory while starting Vulkan (" + call + "); close other programs and try again";
        default:
            return call;
    }
}

struct MadeInstance {
    VkInstance instance = VK_NULL_HANDLE;
    std::string error;  // with instance null: the machine has no usable Vulkan
};

MadeInstance makeInstance(const InstanceConfig& config) {
    if (config.validation && !layerAvailable(kValidationLayer))
        throw Error("Vulkan validation was requested but VK_LAYER_KHRONOS_validation is not installed; install "
                    "the Debian package vulkan-validationlayers, or point VK_LAYER_PATH at the folder of its "
                    "VkLayer_khronos_validation.json");
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "penumbra";
    app.pEngineName = "penumbra";
    app.apiVersion = VK_API_VERSION_1_2;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    const char* layers[] = {kValidationLayer};
    std::vector<const char*> extensions;
    for (const std::string& e : config.extensions) extensions.push_back(e.c_str());
    VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    if (config.validation) {
        info.enabledLayerCount = 1;
        info.ppEnabledLayerNames = layers;
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        messenger.messageSeverity =
            VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
        // Validation only: the loader's own complaints (no driver found) come back as a VkResult,
        // which describeFailure turns into one line.
        messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
        messenger.pfnUserCallback = onInstanceMessage;
        info.pNext = &messenger;
    }
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkInstance instance = VK_NULL_HANDLE;
    const std::uint64_t earlier = vulkanTally().instancesCreated;
    VkResult r = vkCreateInstance(&info, nullptr, &instance);
    if (r == VK_SUCCESS) {
        tally::instanceCreated();
        pinLoadedLibraries();
        return {instance, {}};
    }
    bool unavailable = false;
    std::string message = describeFailure(r, extensions, config.validation, earlier, &unavailable);
    if (!unavailable) throw Error(message);
    return {VK_NULL_HANDLE, message};
}

// A text that tells configurations apart: the cache key.
std::string configKey(const InstanceConfig& config) {
    std::vector<std::string> extensions = config.extensions;
    std::sort(extensions.begin(), extensions.end());
    extensions.erase(std::unique(extensions.begin(), extensions.end()), extensions.end());
    std::string key = config.validation ? "validation" : "plain";
    for (const std::string& e : extensions) key += " " + e;
    return key;
}

// The cache of process-lifetime instances. Never destroyed itself (a static destructor could run
// after the driver's own exit handlers); releaseAtExit empties it instead.
struct Registry {
    std::mutex mutex;
    std::map<std::string, std::shared_ptr<SharedInstance>> instances;
    bool exited = false;
};

Registry& registry() {
    static Registry* r = new Registry;
    return *r;
}

// Lets go of the cached instances at exit: each one no Context still uses is destroyed now; one
// still in use dies with its last Context. Registered with atexit after every vkCreateInstance
// that fills the cache, so it runs before the exit handlers the driver installed while making
// that instance (atexit runs handlers in reverse order; NVIDIA's driver installs one).
void releaseAtExit() {
    std::map<std::string, std::shared_ptr<SharedInstance>> doomed;
    {
        std::lock_guard lock(registry().mutex);
        registry().exited = true;
        doomed.swap(registry().instances);
    }
}

}  // namespace

SharedInstance::SharedInstance(VkInstance instance, InstanceConfig config)
    : instance_(instance), config_(std::move(config)) {}

SharedInstance::~SharedInstance() {
    vkDestroyInstance(instance_, nullptr);
    tally::instanceDestroyed();
}

bool instancePerContext() {
    const char* v = std::getenv("PENUMBRA_INSTANCE_PER_CONTEXT");
    return v && *v && std::strcmp(v, "0") != 0;
}

InstanceResult acquireInstance(const InstanceConfig& config) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    const bool cache = !instancePerContext() && !r.exited;
    const std::string key = configKey(config);
    if (cache) {
        auto found = r.instances.find(key);
        if (found != r.instances.end()) return {found->second, {}};
    }
    MadeInstance made = makeInstance(config);
    if (!made.instance) return {nullptr, made.error};
    auto instance = std::make_shared<SharedInstance>(made.instance, config);
    if (cache) {
        r.instances[key] = instance;
        std::atexit(releaseAtExit);
    }
    return {instance, {}};
}

}  // namespace penumbra::gpu
