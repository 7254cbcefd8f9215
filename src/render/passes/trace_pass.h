// The path-tracing pass: adds samplesPerPass paths per pixel into the accumulation buffer, with
// the megakernel (trace.comp: a thread follows its pixel's paths from camera to end) or the
// wavefront kernels (render/passes/wavefront_pass.h). Both give the same image.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/pipeline.h"
#include "render/gpu_scene.h"
#include "render/passes/wavefront_pass.h"
#include "render/tuning.h"

namespace penumbra {

// TraceKernel (render/tuning.h): Auto picks the wavefront from this many paths per pass on.
constexpr std::uint64_t kWavefrontMinPaths = std::uint64_t(1) << 18;

class TracePass {
public:
    // spec: what the kernels are specialised for (render/kernel_features.h). activeMask: one
    // uint per pixel that record(..., masked = true) obeys (adaptive sampling); without one the
    // pass binds a placeholder of its own and never reads it.
    TracePass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
              const gpu::Buffer& accumulation, const gpu::Buffer& counters, KernelSpec spec,
              const gpu::Buffer* activeMask = nullptr, TraceKernel kernel = renderTuning().traceKernel);

    // The design a pass of width x height x samplesPerPass paths runs with (never Auto).
    TraceKernel kernelFor(std::uint32_t width, std::uint32_t height, std::uint32_t samplesPerPass) const;
    // What the driver says of the tracing kernels made so far (registers, spills...); names
    // prefixed by kernel.
    std::vector<gpu::PipelineStatistic> statistics() const;
    // The wavefront's stage times (WavefrontPass::stageMilliseconds); empty for the megakernel.
    std::map<std::string, double> stageMilliseconds() const;

    // Makes room for passes of width x height x samplesPerPass paths up front (the wavefront's
    // working buffers), so that record never has to wait for the device to grow them.
    void reserve(std::uint32_t width, std::uint32_t height, std::uint32_t samplesPerPass);

    // masked: pixels whose mask entry is 0 take no samples (needs the constructor's activeMask).
    // One dispatch (megakernel) or wavefront round per tile of at most pathBudget() paths
    // (render/passes/trace_tiles.h). maxBounces must be the frame uniforms' value.
    void record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height, std::uint32_t samplesPerPass,
                std::uint32_t passIndex, std::uint32_t maxBounces, bool countRays, bool masked = false);

    // On: each pass stores its sums over the accumulation buffer instead of adding to them, so a
    // caller that takes one pass per frame (the viewer) need not clear the buffer first. Only for
    // passes that sample every pixel (not masked).
    void setReplacesAccumulation(bool on) { replace_ = on; }
    // On: a pixel's samples in one pass of several share their camera ray (PN_TRACE_SHARED_CAMERA),
    // which the wavefront then traces once per pixel; successive passes move it over the pixel
    // evenly (shared/pass_jitter.h). For callers that take many passes (the viewer), not for a
    // few passes of many samples.
    void setSharesCameraRays(bool on) { shareCamera_ = on; }
    // A vec4 per pixel holding its value so far per sample (rgb, lib/pixel_estimate.glsl), which scales the
    // shadow-ray roulette (FrameUniforms::shadowRouletteShare) of every later pass: for callers
    // that replace the sums every pass (the viewer keeps its history's mean there). Without one, a
    // pass that adds to the sums estimates from them. Call before the first pass is recorded.
    void setPixelEstimates(const gpu::Buffer* estimates);

    // Paths per dispatch: by device type unless set (0 puts the device's default back), never more
    // than the wavefront's working buffers can hold on this device.
    std::uint64_t pathBudget() const { return pathBudget_; }
    void setPathBudget(std::uint64_t paths);

private:
    // The kernels are made on first use: a renderer of one size compiles only one design.
    const gpu::ComputePipeline& megakernel();
    TraceOutputs outputs() const;
    WavefrontPass& wavefront();

    const gpu::Context& ctx_;
    const GpuScene& scene_;
    const gpu::Buffer &frameUniforms_, &accumulation_, &counters_;
    const gpu::Buffer* activeMask_;
    const gpu::Buffer* pixelEstimates_ = nullptr;
    KernelSpec spec_;
    TraceKernel kernel_;
    gpu::Buffer placeholderMask_;
    bool hasMask_;
    bool replace_ = false;
    bool shareCamera_ = false;
    std::uint64_t defaultBudget_, pathBudget_;
    std::uint64_t maxBudget_;  // the wavefront's working buffers bound it
    std::unique_ptr<gpu::ComputePipeline> pipeline_;  // the megakernel
    std::unique_ptr<WavefrontPass> wave_;              // the wavefront kernels
};

}  // namespace penumbra
