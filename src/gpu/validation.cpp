#include "gpu/validation.h"

#include <cstdio>

#include "core/error.h"
#include "gpu/check.h"
#include "gpu/instance.h"

namespace penumbra::gpu {
namespace {

std::uint64_t handleBits(const void* handle) { return reinterpret_cast<std::uintptr_t>(handle); }

// Whether a message concerns the sink's device: it names that device or its queue, or it names no
// device or queue at all (then no other Context can claim it either). Before the device exists
// (during vkCreateDevice), every message is kept.
bool concerns(const Messenger::Sink& sink, const VkDebugUtilsMessengerCallbackDataEXT& data) {
    const std::uint64_t device = sink.device.load(), queue = sink.queue.load();
    if (device == 0) return true;
    bool mine = false, other = false;
    for (std::uint32_t i = 0; i < data.objectCount; ++i) {
        const VkDebugUtilsObjectNameInfoEXT& o = data.pObjects[i];
        if (o.objectType != VK_OBJECT_TYPE_DEVICE && o.objectType != VK_OBJECT_TYPE_QUEUE) continue;
        const bool same = o.objectHandle == (o.objectType == VK_OBJECT_TYPE_DEVICE ? device : queue);
        (same ? mine : other) = true;
    }
    return mine || !other;
}

VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    const auto& sink = *static_cast<const Messenger::Sink*>(user);
    if (data && !concerns(sink, *data)) return VK_FALSE;
    std::string message = data && data->pMessage ? data->pMessage : "(no message)";
    if (sink.print) std::fprintf(stderr, "penumbra: vulkan validation: %s\n", message.c_str());
    sink.log->record(std::move(message));
    return VK_FALSE;
}

}  // namespace

void ValidationLog::record(std::string message) {
    std::lock_guard lock(mutex_);
    messages_.push_back(std::move(message));
}

std::vector<std::string> ValidationLog::messages() const {
    std::lock_guard lock(mutex_);
    return messages_;
}

std::size_t ValidationLog::size() const {
    std::lock_guard lock(mutex_);
    return messages_.size();
}

Messenger::Messenger(std::shared_ptr<SharedInstance> instance, std::shared_ptr<ValidationLog> log, bool print)
    : instance_(std::move(instance)), sink_(std::make_unique<Sink>()) {
    sink_->log = std::move(log);
    sink_->print = print;
    VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
    info.pfnUserCallback = onMessage;
    info.pUserData = sink_.get();
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_->get(), "vkCreateDebugUtilsMessengerEXT"));
    if (!create) throw Error("the Vulkan loader lacks vkCreateDebugUtilsMessengerEXT (VK_EXT_debug_utils)");
    std::lock_guard lock(instance_->childMutex());
    PN_VK(create(instance_->get(), &info, nullptr, &messenger_));
}

Messenger::~Messenger() {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_->get(), "vkDestroyDebugUtilsMessengerEXT"));
    std::lock_guard lock(instance_->childMutex());
    if (destroy && messenger_) destroy(instance_->get(), messenger_, nullptr);
}

void Messenger::setDevice(VkDevice device, VkQueue queue) {
    sink_->device = handleBits(device);
    sink_->queue = handleBits(queue);
}

}  // namespace penumbra::gpu
