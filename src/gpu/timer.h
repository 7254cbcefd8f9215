// GPU timestamps around passes: the only honest way to time GPU work.
#pragma once

#include <string>
#include <vector>

#include "gpu/context.h"
#include "gpu/handle.h"

namespace penumbra::gpu {

class GpuTimer {
public:
    GpuTimer(const Context& ctx, std::uint32_t maxSections);

    // Resets the queries on the host; call before recording a command buffer that uses them.
    void reset();
    void begin(VkCommandBuffer cmd, std::uint32_t section);
    void end(VkCommandBuffer cmd, std::uint32_t section);
    // Milliseconds of a section, after the command buffer finished; -1 when unsupported.
    double milliseconds(std::uint32_t section) const;
    bool supported() const { return ctx_.timestampsSupported(); }

private:
    const Context& ctx_;
    std::uint32_t sections_;
    QueryPool pool_;
};

}  // namespace penumbra::gpu
