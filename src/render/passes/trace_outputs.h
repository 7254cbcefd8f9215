// What every tracing kernel (trace.comp, wave_*.comp) writes and obeys besides the scene: the C++
// side of shaders/lib/trace_outputs.glsl, and the one place that makes such a kernel with them bound.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/pipeline.h"
#include "render/gpu_scene.h"
#include "render/kernel_features.h"

namespace penumbra {

struct TraceOutputs {
    const gpu::Buffer* accumulation;    // vec4 per pixel: the sums
    const gpu::Buffer* counters;        // RayCounters
    const gpu::Buffer* activeMask;      // uint per pixel: adaptive sampling's mask
    const gpu::Buffer* pixelEstimates;  // vec4 per pixel: the shadow-ray roulette's scale
};

// A scene pipeline (render/scene_pipeline.h) for a tracing kernel, with the outputs bound;
// moreBindings: the kernel's own storage buffers besides them, left for the caller to bind.
std::unique_ptr<gpu::ComputePipeline> makeTracePipeline(const gpu::Context& ctx, const std::string& shader,
                                                        const GpuScene& scene, const gpu::Buffer& frameUniforms,
                                                        const TraceOutputs& outputs,
                                                        const std::vector<std::uint32_t>& moreBindings,
                                                        KernelSpec spec,
                                                        std::uint32_t camera = PN_CAMERA_FROM_QUEUE);

}  // namespace penumbra
