#include "gpu/check.h"

#include <vulkan/vk_enum_string_helper.h>

#include <string>

#include "core/error.h"

namespace penumbra::gpu {

void throwVkError(const char* call, VkResult result, const char* file, int line) {
    std::string hint;
    if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
        hint = "; out of memory: try a smaller --width/--height or a smaller scene";
    else if (result == VK_ERROR_DEVICE_LOST)
        hint = "; the GPU driver reset the device (a pass may have run too long)";
    throw Error(std::string("Vulkan call failed: ") + call + " returned " + string_VkResult(result) + " (" + file +
                ":" + std::to_string(line) + ")" + hint);
}

}  // namespace penumbra::gpu
