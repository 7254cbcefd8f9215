// Validation messages for one Context. The instance is shared by every Context, so each Context
// has its own debug messenger, which keeps the messages that concern its device. The log outlives
// the Context on purpose: leaked objects are reported while the device is destroyed, and a test
// reads the log after that.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace penumbra::gpu {

class SharedInstance;

class ValidationLog {
public:
    void record(std::string message);
    std::vector<std::string> messages() const;
    std::size_t size() const;

private:
    mutable std::mutex mutex_;
    std::vector<std::string> messages_;
};

// A VK_EXT_debug_utils messenger that records warnings and errors into a log (and prints them to
// stderr unless `print` is false).
// A message that names a device or queue other than this Context's belongs to another Context on
// the same instance and is left to that one's messenger; a message naming none is kept.
class Messenger {
public:
    Messenger(std::shared_ptr<SharedInstance> instance, std::shared_ptr<ValidationLog> log, bool print = true);
    ~Messenger();
    Messenger(const Messenger&) = delete;
    Messenger& operator=(const Messenger&) = delete;

    // The device (and its queue) whose messages this messenger keeps, once it exists.
    void setDevice(VkDevice device, VkQueue queue);

    struct Sink {
        std::shared_ptr<ValidationLog> log;
        bool print = true;
        std::atomic<std::uint64_t> device{0}, queue{0};
    };

private:
    std::shared_ptr<SharedInstance> instance_;
    std::unique_ptr<Sink> sink_;  // the callback's user data: its address must not move
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
};

}  // namespace penumbra::gpu
