// Every Vulkan call goes through PN_VK: a failure becomes a penumbra::Error naming the call,
// the VkResult (string_VkResult), file and line. Always on, in every build.
#pragma once

#include <vulkan/vulkan.h>

namespace penumbra::gpu {

[[noreturn]] void throwVkError(const char* call, VkResult result, const char* file, int line);

}  // namespace penumbra::gpu

#define PN_VK(call)                                                                   \
    do {                                                                              \
        VkResult pn_vk_result_ = (call);                                              \
        if (pn_vk_result_ != VK_SUCCESS)                                              \
            ::penumbra::gpu::throwVkError(#call, pn_vk_result_, __FILE__, __LINE__);  \
    } while (0)
