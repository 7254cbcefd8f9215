// Headless progressive rendering: owns the GPU scene, the accumulation buffer and the passes.
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "gpu/timer.h"
#include "image/image.h"
#include "render/gpu_scene.h"
#include "render/passes/trace_pass.h"
#include "render/settings.h"

namespace penumbra {

struct RenderStats {
    std::uint32_t samplesPerPixel = 0;  // accumulated so far
    std::uint64_t closestRays = 0;
    std::uint64_t shadowRays = 0;
    std::uint64_t invalidSamples = 0;   // NaN/inf path samples (dropped); should stay 0
    // With setFrameStatistics(true) only: primitives tested, closest hits, blocked shadow rays.
    std::uint64_t primitivesTested = 0, closestHits = 0, shadowBlocked = 0;
    double gpuMilliseconds = 0;         // GPU time of the trace passes, from timestamps
};

class Renderer {
public:
    Renderer(const gpu::Context& ctx, const Scene& scene, const RenderSettings& settings);
    ~Renderer();

    // Renders until settings.samplesPerPixel samples are accumulated, calling onProgress with the
    // sample count after each submission.
    void render(const std::function<void(std::uint32_t)>& onProgress = {});
    // Adds `passes` more passes in one submission; returns its GPU milliseconds (-1 if the device
    // has no timestamps). countRays=false keeps the ray-count atomics out of timed runs.
    // masked: only pixels whose active-mask entry is nonzero take samples (setActiveMask).
    double renderPasses(std::uint32_t passes, bool countRays = true, bool masked = false);

    // For final renders in rounds (render/progressive.h): the mask masked passes obey (one uint
    // per pixel), reading the sums back and starting the buffer afresh, putting saved sums back
    // (resuming a checkpoint), and the pass index the next pass gets (its random numbers depend
    // on it, so a resumed render continues where the interrupted one stopped).
    void setActiveMask(std::span<const std::uint32_t> mask);
    std::vector<Vec4> takeAccumulation();  // accumulation(), then zeroes the buffer
    void loadAccumulation(std::span<const Vec4> sums);
    // Drops every sample so far and looks through `camera` from now on: one pipeline for several
    // views of a scene (compiling it is most of a small render's time).
    void restart(const Camera& camera);
    // The same at another moment of animated textures (RenderSettings::time): a walk's frames.
    void restart(const Camera& camera, float time);
    // A material's emission changed where light sampling does not look (a Doom sector's light:
    // found by rays only, so no light table depends on it): the GPU's copy is updated in place,
    // as InteractiveRenderer does, instead of a new Renderer. Call restart() after.
    void setUnsampledEmission(std::uint32_t material, Vec3 emission);
    // A material's textures or alpha cutoff changed (a Doom switch turned, a key was picked up):
    // updated in place; kernels that lack what it now needs are remade. Its emission must stay
    // as it was (the light tables weigh emitters by power). Call restart() after.
    void setMaterial(std::uint32_t index, const Material& material);
    // Moves the instances to where `scene` (the scene this renderer was made from, its instances
    // moved: a Doom door, an animation) now places them: the top level is rebuilt on the CPU and
    // copied over the GPU's, as InteractiveRenderer::setInstanceTransforms does, instead of a new
    // Renderer. Instances of emissive prototypes stay where they were baked (moveInstances). The
    // light grid keeps the bounds the scene had when built: points a move takes beyond them use
    // the light tree's own weights (unbiased; a new renderer would fit them). Call restart() after.
    void setInstanceTransforms(const Scene& scene);
    std::uint32_t passesDone() const { return passesDone_; }
    void setPassesDone(std::uint32_t passes);

    // Mean radiance per pixel so far (top row first).
    ImageRgb image();
    // Raw accumulation: rgb = sum of samples, a = sum of squared luminance.
    std::vector<Vec4> accumulation();

    const RenderStats& stats() const { return stats_; }
    const SceneArrays& sceneArrays() const { return arrays_; }
    const GpuScene& gpuScene() const { return *gpuScene_; }
    const RenderSettings& settings() const { return settings_; }
    const gpu::Buffer& frameUniforms() const { return frameUniforms_; }
    KernelSpec kernelSpec() const { return spec_; }  // what its kernels were specialised for
    // On: later passes also count primitive tests, closest hits and blocked shadow rays
    // (PN_OPTION_FRAME_STATS; remakes the trace kernels). Off by default: counting costs.
    void setFrameStatistics(bool on);

private:
    void makeTracePass();  // with spec_
    // The frame's uniforms for this camera; the rest tree's flat walk while every instance rests.
    shader::FrameUniforms sceneUniforms(const Camera& camera) const;

    const gpu::Context& ctx_;
    RenderSettings settings_;
    SceneArrays arrays_;
    gpu::Commands commands_;
    std::unique_ptr<GpuScene> gpuScene_;
    Vec3 background_;
    Environment environment_;  // intensity and rotation only (the map itself is on the GPU)
    gpu::Buffer frameUniforms_;
    gpu::Buffer accumulation_;
    gpu::Buffer counters_;
    gpu::Buffer activeMask_;  // uint per pixel (adaptive sampling)
    KernelSpec spec_;
    gpu::Buffer instanceStaging_;  // what a move uploads (render/instance_upload.h); made on the first move
    std::unique_ptr<TracePass> trace_;
    gpu::GpuTimer timer_;
    std::uint32_t passesDone_ = 0;
    RenderStats stats_;
};

}  // namespace penumbra
