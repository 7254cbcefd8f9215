// The wavefront trace pass (Laine, Karras & Aila 2013, "Megakernels Considered Harmful"): the
// megakernel's path tracer (trace.comp) cut into kernels that each hold only what their step
// needs: start (camera rays), extend (closest hits), shade (emission, light and BSDF samples,
// roulette), shadow (occlusion), finish (sums into the accumulation buffer). Paths live in slots
// of working buffers between the kernels; the live ones and the shadow rays are compacted into
// queues whose lengths size each pass through indirect dispatches (wave_args.comp). Every path
// draws the megakernel's random numbers in its order, so both give the same image.
#pragma once

#include <memory>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/pipeline.h"
#include "render/gpu_scene.h"
#include "render/passes/trace_tiles.h"

namespace penumbra {

class WavefrontPass {
public:
    WavefrontPass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
                  const gpu::Buffer& accumulation, const gpu::Buffer& counters, const gpu::Buffer& activeMask,
                  std::uint32_t features);

    // The most path slots this device can give the working buffers: the path array within the
    // largest storage buffer a shader may bind, and all of them within a quarter of the memory.
    static std::uint64_t maxSlots(const gpu::Context& ctx);

    // Working buffers for `slots` paths at once. Growing replaces them, after waiting for the
    // device to finish work that uses the old ones; call outside any recording that has already
    // dispatched this pass's kernels.
    void reserve(std::uint64_t slots);

    // One pass over `tile`: its pixels (clipped to width x height) times samplesPerPass paths,
    // maxBounces + 1 closest-hit rays at most per path. Reserves what the tile needs first.
    void record(VkCommandBuffer cmd, const TraceTile& tile, std::uint32_t width, std::uint32_t height,
                std::uint32_t samplesPerPass, std::uint32_t passIndex, std::uint32_t maxBounces, bool countRays,
                bool masked);

    // The driver's statistics of the kernels that matter (extend, shade, shadow), names prefixed.
    std::vector<gpu::PipelineStatistic> statistics() const;

private:
    void bindWorkingBuffers();

    const gpu::Context& ctx_;
    std::uint64_t capacity_ = 0;  // path slots the working buffers hold
    gpu::Buffer paths_, hits_, shadows_, queues_, control_;
    std::unique_ptr<gpu::ComputePipeline> start_, args_, extend_, shade_, shadow_, finish_;
};

}  // namespace penumbra
