// The wavefront trace pass (Laine, Karras & Aila 2013, "Megakernels Considered Harmful"): the
// megakernel's path tracer (trace.comp) cut into kernels that each hold only what their step
// needs: start (camera rays), extend (closest hits), shade (emission, light and BSDF samples,
// roulette), shadow (occlusion), tail (the few paths left, each to its end), finish (sums into
// the accumulation buffer). Paths live in slots of working buffers between the kernels; the live
// ones and the shadow rays are compacted into queues whose lengths size each pass through indirect
// dispatches (wave_args.comp). Every path draws the megakernel's random numbers in its order, so
// both give the same image.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/pipeline.h"
#include "gpu/timer.h"
#include "render/gpu_scene.h"
#include "render/kernel_features.h"
#include "render/passes/trace_outputs.h"
#include "render/passes/trace_tiles.h"

namespace penumbra {

class WavefrontPass {
public:
    WavefrontPass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
                  const TraceOutputs& outputs, KernelSpec spec);

    // The most path slots this device can give the working buffers: the path array within the
    // largest storage buffer a shader may bind, and all of them within a quarter of the memory.
    static std::uint64_t maxSlots(const gpu::Context& ctx);

    // Working buffers for `slots` paths at once. Growing replaces them, after waiting for the
    // device to finish work that uses the old ones; call outside any recording that has already
    // dispatched this pass's kernels.
    void reserve(std::uint64_t slots);

    // Before a pass's tiles: collects the last pass's stage times (diagnostics, below).
    void beginPass(VkCommandBuffer cmd);

    // One pass over `tile`: its pixels (clipped to width x height) times samplesPerPass paths,
    // maxBounces + 1 closest-hit rays at most per path; traceMode: PN_TRACE_MASKED and
    // PN_TRACE_REPLACE bits. Reserves what the tile needs first.
    void record(VkCommandBuffer cmd, const TraceTile& tile, std::uint32_t width, std::uint32_t height,
                std::uint32_t samplesPerPass, std::uint32_t passIndex, std::uint32_t maxBounces, bool countRays,
                std::uint32_t traceMode);

    // The driver's statistics of the kernels that matter (extend, shade, shadow), names prefixed.
    std::vector<gpu::PipelineStatistic> statistics() const;

    // Diagnostics, with PENUMBRA_WAVE_STAGE_TIMES=1: the median GPU milliseconds per pass of each
    // step (start, extend, shade, shadow, tail, finish; summed over bounces and tiles), and of each step
    // at each round of the bounce loop ("extend.b1": its second round; a round's shadow step
    // traces the rays the previous round's shading queued; finish counts with the last round), over
    // the passes whose timestamps had
    // landed when the next pass was recorded. The steps are then separated by barriers to be
    // timed alone, so the pass itself is a little slower. Empty otherwise.
    std::map<std::string, double> stageMilliseconds() const;

private:
    void bindWorkingBuffers();
    // Around one dispatch of `stage` in round `round` of the bounce loop when stage timing is on.
    template <typename Dispatch>
    void timed(VkCommandBuffer cmd, std::uint32_t stage, std::uint32_t round, Dispatch&& dispatch);
    void collectStageTimes(VkCommandBuffer cmd);

    const gpu::Context& ctx_;
    std::uint64_t capacity_ = 0;  // path slots the working buffers hold
    std::uint32_t tailPaths_ = 0;  // PassPush.waveTailPaths
    gpu::Buffer paths_, hits_, shadows_, queues_, control_;
    std::unique_ptr<gpu::ComputePipeline> start_, args_, extend_, shade_, shadow_, tail_, finish_;
    // Bounce 0's extend and shade when they make the camera paths (PN_CAMERA_IN_PLACE).
    std::unique_ptr<gpu::ComputePipeline> extendCamera_, shadeCamera_;
    struct StageTimes {
        explicit StageTimes(const gpu::Context& ctx) : timer(ctx, kSections) {}
        static constexpr std::uint32_t kSections = 256;
        gpu::GpuTimer timer;
        struct Section {
            std::uint32_t stage, round;
        };
        std::vector<Section> sections;  // what each timer section recorded since the last reset timed
        std::map<std::string, std::vector<double>> perPass;
    };
    std::unique_ptr<StageTimes> stageTimes_;
};

}  // namespace penumbra
