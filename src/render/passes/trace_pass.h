// The path-tracing pass: adds samplesPerPass paths per pixel into the accumulation buffer.
#pragma once

#include <memory>

#include "gpu/pipeline.h"
#include "render/gpu_scene.h"

namespace penumbra {

class TracePass {
public:
    // features: what the kernel is specialised for (render/kernel_features.h).
    TracePass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
              const gpu::Buffer& accumulation, const gpu::Buffer& counters, std::uint32_t features);

    const gpu::ComputePipeline& pipeline() const { return *pipeline_; }

    void record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height, std::uint32_t passIndex,
                bool countRays) const;

private:
    std::unique_ptr<gpu::ComputePipeline> pipeline_;
};

}  // namespace penumbra
