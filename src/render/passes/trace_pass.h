// The path-tracing pass: adds samplesPerPass paths per pixel into the accumulation buffer.
#pragma once

#include <memory>

#include "gpu/pipeline.h"
#include "render/gpu_scene.h"

namespace penumbra {

class TracePass {
public:
    TracePass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
              const gpu::Buffer& accumulation, const gpu::Buffer& counters);

    void record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height, std::uint32_t passIndex,
                bool countRays) const;

private:
    std::unique_ptr<gpu::ComputePipeline> pipeline_;
};

}  // namespace penumbra
