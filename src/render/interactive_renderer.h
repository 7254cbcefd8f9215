// The viewer's frame: trace (this frame's samples) -> G-buffer -> temporal accumulation ->
// optional a-trous denoiser -> tonemap into an RGBA8 display buffer; or a debug view. Records
// into the caller's command buffer so the window can add its copy, UI and present to the same
// submission. Resolution changes rebuild the per-pixel buffers, never the scene.
#pragma once

#include <memory>
#include <optional>

#include "gpu/commands.h"
#include "gpu/timer.h"
#include "render/gpu_scene.h"
#include "render/passes/box_overlay_pass.h"
#include "render/passes/denoise_pass.h"
#include "render/passes/gbuffer_pass.h"
#include "render/passes/temporal_pass.h"
#include "render/passes/tonemap_pass.h"
#include "render/passes/trace_pass.h"
#include "render/settings.h"
#include "render/view_settings.h"

namespace penumbra {

// Frame spans the whole recorded frame (every pass, barrier and copy), the others one pass each.
enum class ViewerPass : std::uint32_t { Trace, GBuffer, Temporal, Denoise, Tonemap, Heatmap, Boxes, Frame, Count };
const char* viewerPassName(ViewerPass pass);

struct ViewerStats {
    std::uint32_t samplesPerPixel = 0;  // accumulated since the last reset (the running mean's N)
    double passMilliseconds[std::size_t(ViewerPass::Count)] = {};  // last frame; -1: no timestamps
    double raysPerSecond = 0;           // last frame's rays over its trace time
    std::uint64_t rays = 0;             // last frame's rays: closest hits and shadow rays
    // Last frame's, with setFrameStatistics(true) (zero otherwise).
    std::uint64_t closestRays = 0, shadowRays = 0;
    std::uint64_t primitivesTested = 0, closestHits = 0, shadowBlocked = 0;
    bool frameStatistics = false;       // whether the last frame counted them
    bool gbufferSkipped = false;        // last frame reused the still view's G-buffer
    bool tonemapInDenoiser = false;     // last frame's denoiser wrote the display (no tonemap pass)
    std::uint32_t heatMaxNodes = 0, heatMaxTriangles = 0;  // last heat-map frame
    std::uint32_t heatMaxLeafDepth = 0, heatMaxLeafTriangles = 0;
};

class InteractiveRenderer {
public:
    // torchIsLastLight: the scene's last light is the camera torch (attachTorch), which then is
    // the last punctual light too; it is moved to the camera every frame and can be switched off.
    // bvhBuild: where the world's BVH is built, here and by rebuildScene (view --bvh-build).
    InteractiveRenderer(const gpu::Context& ctx, const Scene& scene, bool torchIsLastLight, std::uint32_t seed = 1,
                        BvhBuild bvhBuild = BvhBuild::Cpu);
    ~InteractiveRenderer();

    // Replaces the scene (moved objects, another file): rebuilds the BVH and every GPU buffer and
    // drops history. A full rebuild: simple, and fast enough for the scenes one edits by hand.
    void rebuildScene(const Scene& scene, bool torchIsLastLight);
    // Re-uploads one material and drops history, and remakes the kernels if the scene now needs
    // other ones (a material turned to glass or metal). Its emission must be unchanged, because
    // the light tables weigh emitters by power (an emission edit needs rebuildScene).
    void setMaterial(std::uint32_t index, const Material& material);
    // New emission for a material that light sampling leaves out (Material::lightSampled false:
    // Doom's sector fill light, which light specials change every few tics). It goes up with the
    // next frame, no wait; the history restarts, since the light changed wherever it reaches.
    void setUnsampledEmission(std::uint32_t index, Vec3 emission);

    // Moves the instances to where `scene` (the scene loaded, its instances moved: an animation,
    // an edited object) now places them: the top level is rebuilt on the CPU and goes to the GPU
    // with the next frame, no bottom level is rebuilt. That frame's motion vectors carry each
    // instance's move since the frame before (its previous transform is kept).
    void setInstanceTransforms(const Scene& scene);
    // Off: the G-buffer sees every instance as still (no object motion in the motion vectors); the
    // comparison the ghost test makes. On by default.
    void setObjectMotionVectors(bool on) { objectMotionVectors_ = on; }
    // Closest-hit walks skip back faces (RenderSettings::cullBackfaces); remakes the kernels and
    // drops history when it changes. Off by default.
    void setCullBackfaces(bool on);
    // The trace kernels also count primitive tests, closest hits and blocked shadow rays into
    // ViewerStats (PN_OPTION_FRAME_STATS); remakes the kernels when it changes. Off by default.
    void setFrameStatistics(bool on);

    // Sets the render resolution; a change reallocates the per-pixel buffers and drops history.
    void resize(std::uint32_t width, std::uint32_t height);
    // The next frame starts a new running mean (use after the scene or lighting changed).
    void resetHistory() { historyValid_ = false; }

    // Writes this frame's uniforms (the previous submission must have finished) and records its
    // passes; the display buffer holds the frame once the submission completes.
    void record(VkCommandBuffer cmd, const Camera& camera, const ViewSettings& settings);
    // Reads the frame's timestamps and counters; call after its submission completed.
    void finishFrame();

    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }
    const gpu::Buffer& display() const { return display_; }  // uint RGBA8 per pixel
    const gpu::Buffer& history() const { return *historyOut_; }  // HistoryTexel per pixel
    const gpu::Buffer& gbuffer() const { return historyOut_ == &historyA_ ? gbufferA_ : gbufferB_; }
    const gpu::Buffer& denoiseGuide() const { return guide_; }  // PN_DENOISE_GUIDE_BYTES per pixel
    // After a heat view's frame: vec4 per pixel (nodes, triangles, leaf depth, leaf primitives).
    const gpu::Buffer& heatCounts() const { return filterB_; }
    // The linear image the tonemap pass read last frame (vec4 per pixel, rgb radiance): the
    // denoiser's output, or null when the denoiser did not run.
    const gpu::Buffer* denoised() const { return denoised_; }
    const ViewerStats& stats() const { return stats_; }
    bool hasTorch() const { return torchLight_.has_value(); }
    const GpuScene& gpuScene() const { return *gpuScene_; }
    // The trace pass's pipeline (for its driver statistics); valid after resize.
    std::vector<gpu::PipelineStatistic> traceStatistics() const { return trace_->statistics(); }
    // The temporal and a-trous pipelines' (the image passes that run every frame).
    std::vector<gpu::PipelineStatistic> imageStatistics() const;
    std::map<std::string, double> traceStageMilliseconds() const { return trace_->stageMilliseconds(); }
    KernelSpec kernelSpec() const { return spec_; }
    const SceneArrays& sceneArrays() const { return arrays_; }
    gpu::Commands& commands() { return commands_; }

private:
    void loadScene(const Scene& scene, SceneArrays arrays, bool torchIsLastLight);
    void createPasses();
    // The kernel features the scene needs as it stands (the viewer always walks the binary BVH).
    KernelSpec sceneKernelSpec() const;
    // Sends moved instances, the rebuilt top level and the previous frame's instances up before
    // this frame's passes; `moved`: the instances differ from the last frame's.
    void uploadInstances(VkCommandBuffer cmd, bool moved);
    // record's steps: the history's reset and swap, the two uniform blocks, the uploads before
    // the passes (torch, instances, cleared counters), the passes, and the box overlay.
    void startHistory(const ViewSettings& s);
    shader::FrameUniforms frameUniforms(const Camera& camera, const ViewSettings& s) const;
    shader::ViewerUniforms viewerUniforms(const ViewSettings& s, const shader::FrameUniforms& f, bool moved) const;
    void recordUploads(VkCommandBuffer cmd, const Camera& camera, const ViewSettings& s, bool instancesMoved, bool heat);
    void recordPasses(VkCommandBuffer cmd, const ViewSettings& s, bool heat, bool denoise, bool moved, bool reuseGBuffer);
    // Records this frame's G-buffer pass unless both letters already hold this still view (reuse).
    void recordGBuffer(VkCommandBuffer cmd, bool toB, bool moved, bool reuse);
    void recordBoxOverlay(VkCommandBuffer cmd, const ViewSettings& s);
    // A fast-preview frame (ViewSettings::preview while moving): G-buffer, then the display.
    void recordPreview(VkCommandBuffer cmd, const Camera& camera, const ViewSettings& s, shader::FrameUniforms f,
                       bool instancesMoved);
    // Records body between the pass's timestamps and notes that the pass ran this frame.
    template <class Body>
    void timed(VkCommandBuffer cmd, ViewerPass pass, Body&& body) {
        timer_.begin(cmd, std::uint32_t(pass));
        body();
        timer_.end(cmd, std::uint32_t(pass));
        recorded_ |= 1u << std::uint32_t(pass);
    }

    const gpu::Context& ctx_;
    SceneArrays arrays_;
    gpu::Commands commands_;
    std::unique_ptr<GpuScene> gpuScene_;
    Vec3 background_;
    Environment environment_;  // intensity and rotation only (the map itself is on the GPU)
    std::optional<std::uint32_t> torchLight_;
    std::uint32_t seed_;
    BvhBuild bvhBuild_ = BvhBuild::Cpu;
    gpu::Buffer frameUniforms_, viewerUniforms_, counters_, heatCounters_;
    // Each frame writes one history and the G-buffer of the same letter, and reads the other two as
    // last frame's: swapping the pair every frame spares copying the G-buffer.
    gpu::Buffer accumulation_, gbufferA_, gbufferB_, historyA_, historyB_, filterA_, filterB_, guide_, display_;
    gpu::Buffer pixelEstimates_;  // vec4 per pixel: the history's mean (rgb), the trace's roulette scale
    // The instances as the previous frame placed them (gbuffer.comp's object motion), and the
    // staging buffer that carries moved instances and the top level up.
    gpu::Buffer instancesPrev_, instanceStaging_;
    std::vector<shader::Instance> lastFrameInstances_;
    std::vector<std::uint32_t> pendingMaterials_;  // materials to upload with the next frame  // as the last recorded frame placed them
    bool prevMatchesCurrent_ = true;  // instancesPrev_ holds the current instances
    bool objectMotionVectors_ = true;
    bool cullBackfaces_ = false;
    bool frameStatistics_ = false;
    gpu::Buffer* historyIn_ = nullptr;  // last frame's history; the two swap every frame
    gpu::Buffer* historyOut_ = nullptr;
    std::unique_ptr<TracePass> trace_;
    // One per letter of the buffers they write (the G-buffer pass, temporal: A to B reads history
    // A and writes B) or read (denoise and tonemap: this frame's G-buffer, and history for tonemap).
    std::unique_ptr<GBufferPass> gbufferPassA_, gbufferPassB_;
    std::unique_ptr<TemporalPass> temporalAB_, temporalBA_;
    std::unique_ptr<DenoisePass> denoiseA_, denoiseB_;
    std::unique_ptr<TonemapPass> tonemapA_, tonemapB_;
    std::unique_ptr<HeatmapPass> heatmap_;
    std::unique_ptr<BoxOverlayPass> boxes_;
    std::optional<std::uint32_t> boxesDepth_;  // the depth boxes_ holds; none: refill it
    gpu::GpuTimer timer_;
    std::uint32_t width_ = 0, height_ = 0;
    KernelSpec spec_;  // what the scene kernels are specialised for
    bool historyValid_ = false;
    // Whether G-buffer A / B holds the current view with no motion. While the camera and the
    // scene hold still, the pixel-centre rays hit the same points every frame: once both letters
    // hold that G-buffer, the pass is not recorded (the temporal pass reads both).
    bool stillGBuffer_[2] = {false, false};
    std::uint32_t frameIndex_ = 0;  // frames since the history was last reset
    // Frames traced since the renderer was made, never reset: the trace pass index that seeds the
    // random numbers, so frames without history (temporal off, settings changed) still differ.
    std::uint32_t tracedFrames_ = 0;
    std::optional<shader::FrameUniforms> previousFrame_;
    std::optional<ViewSettings> previousSettings_;
    bool heatFrame_ = false;
    const gpu::Buffer* denoised_ = nullptr;
    std::uint32_t recorded_ = 0;  // bit per ViewerPass timed this frame
    ViewerStats stats_;
};

}  // namespace penumbra
