#include "gpu/timer.h"

#include "core/error.h"
#include "gpu/check.h"

namespace penumbra::gpu {

GpuTimer::GpuTimer(const Context& ctx, std::uint32_t maxSections) : ctx_(ctx), sections_(maxSections) {
    if (!supported()) return;
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2 * maxSections;
    VkQueryPool pool = VK_NULL_HANDLE;
    PN_VK(vkCreateQueryPool(ctx.device(), &info, nullptr, &pool));
    pool_ = QueryPool(ctx.device(), pool);
    reset();
}

void GpuTimer::reset() {
    if (supported()) vkResetQueryPool(ctx_.device(), pool_.get(), 0, 2 * sections_);
}

void GpuTimer::reset(VkCommandBuffer cmd) {
    if (supported()) vkCmdResetQueryPool(cmd, pool_.get(), 0, 2 * sections_);
}

void GpuTimer::begin(VkCommandBuffer cmd, std::uint32_t section) {
    PN_CHECK(section < sections_);
    if (supported()) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_.get(), 2 * section);
}

void GpuTimer::end(VkCommandBuffer cmd, std::uint32_t section) {
    PN_CHECK(section < sections_);
    if (supported()) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_.get(), 2 * section + 1);
}

double GpuTimer::milliseconds(std::uint32_t section) const {
    if (!supported()) return -1.0;
    std::uint64_t stamps[2] = {};
    PN_VK(vkGetQueryPoolResults(ctx_.device(), pool_.get(), 2 * section, 2, sizeof(stamps), stamps,
                                sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    return double(stamps[1] - stamps[0]) * ctx_.timestampPeriodNs() * 1e-6;
}

std::optional<double> GpuTimer::millisecondsIfReady(std::uint32_t section) const {
    if (!supported()) return std::nullopt;
    std::uint64_t stamps[4] = {};  // value, availability; value, availability
    const VkResult r = vkGetQueryPoolResults(ctx_.device(), pool_.get(), 2 * section, 2, sizeof(stamps), stamps,
                                             2 * sizeof(std::uint64_t),
                                             VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
    if (r == VK_NOT_READY || stamps[1] == 0 || stamps[3] == 0) return std::nullopt;
    PN_VK(r);
    return double(stamps[2] - stamps[0]) * ctx_.timestampPeriodNs() * 1e-6;
}

}  // namespace penumbra::gpu
