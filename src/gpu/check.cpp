#include "gpu/check.h"

#include <string>

#include "core/error.h"

namespace penumbra::gpu {

const char* resultName(VkResult result) {
    switch (result) {
#define PN_CASE(r) \
    case r:        \
        return #r;
        PN_CASE(VK_SUCCESS)
        PN_CASE(VK_NOT_READY)
        PN_CASE(VK_TIMEOUT)
        PN_CASE(VK_INCOMPLETE)
        PN_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        PN_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        PN_CASE(VK_ERROR_INITIALIZATION_FAILED)
        PN_CASE(VK_ERROR_DEVICE_LOST)
        PN_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        PN_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        PN_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
        PN_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        PN_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
        PN_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        PN_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        PN_CASE(VK_ERROR_FRAGMENTED_POOL)
        PN_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
        PN_CASE(VK_ERROR_UNKNOWN)
#undef PN_CASE
        default:
            return "VkResult(unknown)";
    }
}

void throwVkError(const char* call, VkResult result, const char* file, int line) {
    std::string hint;
    if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
        hint = "; try a smaller --width/--height or a smaller scene";
    else if (result == VK_ERROR_DEVICE_LOST)
        hint = "; the GPU driver reset the device (a pass may have run too long)";
    throw Error(std::string("Vulkan call failed: ") + call + " returned " + resultName(result) +
                " (" + file + ":" + std::to_string(line) + ")" + hint);
}

}  // namespace penumbra::gpu
