#include "gpu/commands.h"

#include "gpu/check.h"

namespace penumbra::gpu {

Commands::Commands(const Context& ctx) : ctx_(ctx) {
    VkDevice device = ctx.device();
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = ctx.queueFamily();
    VkCommandPool pool = VK_NULL_HANDLE;
    PN_VK(vkCreateCommandPool(device, &poolInfo, nullptr, &pool));
    pool_ = CommandPool(device, pool);

    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    PN_VK(vkAllocateCommandBuffers(device, &alloc, &cmd_));

    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence = VK_NULL_HANDLE;
    PN_VK(vkCreateFence(device, &fenceInfo, nullptr, &fence));
    fence_ = Fence(device, fence);
}

Commands::~Commands() = default;  // run() never leaves a submission behind; the pool frees its buffer

void Commands::run(const std::function<void(VkCommandBuffer)>& record) {
    PN_VK(vkResetCommandBuffer(cmd_, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    PN_VK(vkBeginCommandBuffer(cmd_, &begin));
    record(cmd_);
    PN_VK(vkEndCommandBuffer(cmd_));

    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd_;
    VkFence fence = fence_.get();
    PN_VK(vkResetFences(ctx_.device(), 1, &fence));
    PN_VK(vkQueueSubmit(ctx_.queue(), 1, &submit, fence));
    try {
        PN_VK(vkWaitForFences(ctx_.device(), 1, &fence, VK_TRUE, UINT64_MAX));
    } catch (...) {
        // The submission may still be running, and the exception is about to unwind the objects
        // it reads (a Renderer's buffers go before its Commands): wait for it before they go.
        // Waiting here, not in ~Commands, is what makes the order of an owner's members not
        // matter. A lost device answers at once; the result changes nothing.
        vkWaitForFences(ctx_.device(), 1, &fence, VK_TRUE, UINT64_MAX);
        throw;
    }
}

void computeBarrier(VkCommandBuffer cmd) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT |
                            VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    VkPipelineStageFlags stages = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    vkCmdPipelineBarrier(cmd, stages, stages, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

void indirectBarrier(VkCommandBuffer cmd) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier, 0,
                         nullptr, 0, nullptr);
}

}  // namespace penumbra::gpu
