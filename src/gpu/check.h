// Every Vulkan call goes through PN_VK: a failure becomes a penumbra::Error naming the call,
// the VkResult (string_VkResult), file and line. Always on, in every build.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>

#include "core/error.h"

namespace penumbra::gpu {

// What PN_VK throws. A lost device or exhausted memory is one line for the user like any Error;
// the result lets a caller that holds something worth keeping (a checkpoint) add to the message.
class VulkanError : public Error {
public:
    VulkanError(const std::string& message, VkResult result) : Error(message), result(result) {}
    VkResult result;
};

[[noreturn]] void throwVkError(const char* call, VkResult result, const char* file, int line);

// Test hook (device loss and out-of-memory cannot be provoked on demand): after `afterCalls` more
// PN_VK calls, every PN_VK call fails with `result` without reaching the driver, as a lost device
// keeps failing. VK_SUCCESS disarms it. PENUMBRA_TEST_VK_FAILURE=RESULT:N (for example
// VK_ERROR_DEVICE_LOST:200) arms it for a whole process.
void injectVkFailure(VkResult result, std::uint64_t afterCalls);
// How many calls are left before the armed failure (tests count a workload's calls this way).
std::uint64_t injectVkFailureCallsLeft();

namespace detail {
extern std::atomic<bool> failureArmed;
VkResult injectedResult();  // VK_SUCCESS: make the call
}  // namespace detail

}  // namespace penumbra::gpu

// An injected failure replaces the call, as a real one would: nothing is created or submitted.
#define PN_VK(call)                                                                   \
    do {                                                                              \
        VkResult pn_vk_result_ = VK_SUCCESS;                                          \
        if (!::penumbra::gpu::detail::failureArmed.load(std::memory_order_relaxed) || \
            (pn_vk_result_ = ::penumbra::gpu::detail::injectedResult()) == VK_SUCCESS) \
            pn_vk_result_ = (call);                                                   \
        if (pn_vk_result_ != VK_SUCCESS)                                              \
            ::penumbra::gpu::throwVkError(#call, pn_vk_result_, __FILE__, __LINE__);  \
    } while (0)
