// The path-tracing pass: adds samplesPerPass paths per pixel into the accumulation buffer.
#pragma once

#include <memory>

#include "gpu/buffer.h"
#include "gpu/pipeline.h"
#include "render/gpu_scene.h"

namespace penumbra {

class TracePass {
public:
    // features: what the kernel is specialised for (render/kernel_features.h). activeMask: one
    // uint per pixel that record(..., masked = true) obeys (adaptive sampling); without one the
    // pass binds a placeholder of its own and never reads it.
    TracePass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
              const gpu::Buffer& accumulation, const gpu::Buffer& counters, std::uint32_t features,
              const gpu::Buffer* activeMask = nullptr);

    const gpu::ComputePipeline& pipeline() const { return *pipeline_; }

    // masked: pixels whose mask entry is 0 take no samples (needs the constructor's activeMask).
    // One dispatch per tile of at most pathBudget() paths (render/passes/trace_tiles.h).
    void record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height, std::uint32_t samplesPerPass,
                std::uint32_t passIndex, bool countRays, bool masked = false) const;

    // Paths per dispatch: by device type unless set (0 puts the device's default back).
    std::uint64_t pathBudget() const { return pathBudget_; }
    void setPathBudget(std::uint64_t paths);

private:
    gpu::Buffer placeholderMask_;
    bool hasMask_;
    std::uint64_t defaultBudget_, pathBudget_;
    std::unique_ptr<gpu::ComputePipeline> pipeline_;
};

}  // namespace penumbra
