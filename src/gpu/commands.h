// Records and submits command buffers on the context's queue and waits for them.
#pragma once

#include <functional>

#include "gpu/context.h"
#include "gpu/handle.h"

namespace penumbra::gpu {

class Commands {
public:
    explicit Commands(const Context& ctx);
    ~Commands();
    Commands(const Commands&) = delete;
    Commands& operator=(const Commands&) = delete;

    // Records `record` into a fresh command buffer, submits it and waits until the GPU is done,
    // also when it throws: nothing it submitted is still running when it returns or throws.
    void run(const std::function<void(VkCommandBuffer)>& record);

private:
    const Context& ctx_;
    CommandPool pool_;
    Fence fence_;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
};

// Makes compute-shader and transfer writes visible to later compute shaders and transfers.
void computeBarrier(VkCommandBuffer cmd);
// Compute writes before indirect dispatches that read their group counts (and shaders that read them).
void indirectBarrier(VkCommandBuffer cmd);

}  // namespace penumbra::gpu
