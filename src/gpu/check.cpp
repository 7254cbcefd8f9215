#include "gpu/check.h"

#include <vulkan/vk_enum_string_helper.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>

namespace penumbra::gpu {
namespace {

std::mutex g_injectMutex;
VkResult g_injectResult = VK_SUCCESS;
std::uint64_t g_callsLeft = 0;

// VK_ERROR_DEVICE_LOST, VK_ERROR_OUT_OF_DEVICE_MEMORY, VK_ERROR_OUT_OF_HOST_MEMORY by name, or VK_SUCCESS.
VkResult resultNamed(const std::string& name) {
    for (VkResult r : {VK_ERROR_DEVICE_LOST, VK_ERROR_OUT_OF_DEVICE_MEMORY, VK_ERROR_OUT_OF_HOST_MEMORY})
        if (name == string_VkResult(r)) return r;
    // Read before main() runs, so a warning rather than an Error nobody could catch.
    std::fprintf(stderr, "penumbra: warning: PENUMBRA_TEST_VK_FAILURE='%s' ignored: use VK_ERROR_DEVICE_LOST, "
                 "VK_ERROR_OUT_OF_DEVICE_MEMORY or VK_ERROR_OUT_OF_HOST_MEMORY, then :N for the calls before it\n",
                 name.c_str());
    return VK_SUCCESS;
}

bool armFromEnvironment() {
    const char* text = std::getenv("PENUMBRA_TEST_VK_FAILURE");
    if (!text || !*text) return false;
    const char* colon = std::strchr(text, ':');
    g_injectResult = resultNamed(colon ? std::string(text, colon) : std::string(text));
    g_callsLeft = colon ? std::strtoull(colon + 1, nullptr, 10) : 0;
    return g_injectResult != VK_SUCCESS;
}

// What to do about it, by result: each is one clause after the call.
std::string hintFor(VkResult result) {
    switch (result) {
        case VK_ERROR_OUT_OF_DEVICE_MEMORY:
            return "; the GPU is out of memory: render a smaller image (--width/--height) or scene, or close other "
                   "programs using the GPU";
        case VK_ERROR_OUT_OF_HOST_MEMORY:
            return "; the driver ran out of system memory: render a smaller image or scene";
        case VK_ERROR_DEVICE_LOST:
            return "; the GPU was lost (a driver reset or GPU fault) and nothing more can run on it: check the "
                   "driver's log (dmesg), then run again, on another device (--device) if it happens again";
        default:
            return "";
    }
}

}  // namespace

namespace detail {

std::atomic<bool> failureArmed{armFromEnvironment()};

VkResult injectedResult() {
    std::lock_guard lock(g_injectMutex);
    if (g_injectResult == VK_SUCCESS) return VK_SUCCESS;
    if (g_callsLeft > 0) {
        --g_callsLeft;
        return VK_SUCCESS;
    }
    return g_injectResult;
}

}  // namespace detail

void injectVkFailure(VkResult result, std::uint64_t afterCalls) {
    std::lock_guard lock(g_injectMutex);
    g_injectResult = result;
    g_callsLeft = afterCalls;
    detail::failureArmed.store(result != VK_SUCCESS);
}

std::uint64_t injectVkFailureCallsLeft() {
    std::lock_guard lock(g_injectMutex);
    return g_callsLeft;
}

void throwVkError(const char* call, VkResult result, const char* file, int line) {
    throw VulkanError(std::string("Vulkan call failed: ") + call + " returned " + string_VkResult(result) + " (" +
                          file + ":" + std::to_string(line) + ")" + hintFor(result),
                      result);
}

}  // namespace penumbra::gpu
