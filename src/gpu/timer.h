// GPU timestamps around passes: the only honest way to time GPU work.
#pragma once

#include <optional>
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
    // Records a reset of every section into cmd instead (for timers read while other passes run).
    void reset(VkCommandBuffer cmd);
    void begin(VkCommandBuffer cmd, std::uint32_t section);
    void end(VkCommandBuffer cmd, std::uint32_t section);
    // Milliseconds of a section, after the command buffer finished; -1 when unsupported.
    double milliseconds(std::uint32_t section) const;
    // The same without waiting: nothing when the section's timestamps have not landed.
    std::optional<double> millisecondsIfReady(std::uint32_t section) const;
    bool supported() const { return ctx_.timestampsSupported(); }

private:
    const Context& ctx_;
    std::uint32_t sections_;
    QueryPool pool_;
};

}  // namespace penumbra::gpu
