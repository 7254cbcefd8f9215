#include "render/interactive_renderer.h"

#include <algorithm>
#include <cstring>
#include <span>
#include <utility>

#include "bvh/depth_boxes.h"
#include "core/error.h"
#include "gpu/check.h"
#include "render/frame_uniforms.h"
#include "render/instance_arrays.h"
#include "render/instance_upload.h"
#include "render/kernel_features.h"
#include "render/passes/gbuffer_pass.h"
#include "render/ray_counters.h"
#include "render/rest_tree.h"
#include "shared/animation.h"

namespace penumbra {
namespace {

constexpr VkBufferUsageFlags kPixelUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

bool sameCamera(const shader::FrameUniforms& a, const shader::FrameUniforms& b) {
    auto same = [](Vec3 x, Vec3 y) { return x.x == y.x && x.y == y.y && x.z == y.z; };
    return same(a.cameraPosition, b.cameraPosition) && same(a.cameraForward, b.cameraForward) &&
           same(a.cameraUp, b.cameraUp) && a.tanHalfFovY == b.tanHalfFovY && a.aspect == b.aspect;
}

bool animationTicked(std::span<const shader::TextureInfo> textures, float before, float now) {
    return std::any_of(textures.begin(), textures.end(), [&](const shader::TextureInfo& t) {
        return t.frameCount > 1 &&
               shader::animationTick(before, t.secondsPerFrame) != shader::animationTick(now, t.secondsPerFrame);
    });
}

// Views drawn from the heat-map pass's per-pixel counts.
bool isHeatView(DebugView v) {
    return v == DebugView::HeatNodes || v == DebugView::HeatTriangles || v == DebugView::LeafDepth ||
           v == DebugView::LeafTriangles;
}

// The count a heat view shows as its hottest colour: the largest of the last heat frame.
std::uint32_t heatScaleMax(DebugView v, const shader::HeatCounters& c) {
    switch (v) {
        case DebugView::HeatNodes: return c.maxNodes;
        case DebugView::HeatTriangles: return c.maxTris;
        case DebugView::LeafDepth: return c.maxLeafDepth;
        default: return c.maxLeafTris;
    }
}

// The box overlay draws over the ordinary image, so the other passes see no debug view.
DebugView shownDebugView(const ViewSettings& s) { return s.debug == DebugView::BvhBoxes ? DebugView::None : s.debug; }

// Settings whose change makes the running mean mix two different images.
bool changesTheImage(const ViewSettings& a, const ViewSettings& b) {
    auto same = [](Vec3 x, Vec3 y) { return x.x == y.x && x.y == y.y && x.z == y.z; };
    return a.apertureRadius != b.apertureRadius || a.focusDistance != b.focusDistance ||
           a.samplesPerFrame != b.samplesPerFrame || a.maxBounces != b.maxBounces ||
           a.rouletteStart != b.rouletteStart || a.shareCameraRays != b.shareCameraRays ||
           a.antiAliasing != b.antiAliasing || a.torch != b.torch ||
           !same(a.torchColor, b.torchColor) || a.torchIntensity != b.torchIntensity || a.torchRange != b.torchRange;
}

void transferToComputeBarrier(VkCommandBuffer cmd) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier,
                         0, nullptr, 0, nullptr);
}

}  // namespace

const char* viewerPassName(ViewerPass pass) {
    switch (pass) {
        case ViewerPass::Trace: return "trace";
        case ViewerPass::GBuffer: return "G-buffer";
        case ViewerPass::Temporal: return "temporal";
        case ViewerPass::Denoise: return "denoise";
        case ViewerPass::Tonemap: return "tonemap";
        case ViewerPass::Heatmap: return "heat map";
        case ViewerPass::Boxes: return "BVH boxes";
        case ViewerPass::Frame: return "frame";
        case ViewerPass::Count: break;
    }
    return "?";
}

InteractiveRenderer::InteractiveRenderer(const gpu::Context& ctx, const Scene& scene, bool torchIsLastLight,
                                         std::uint32_t seed, BvhBuild bvhBuild)
    : ctx_(ctx), commands_(ctx), seed_(seed), bvhBuild_(bvhBuild), timer_(ctx, std::uint32_t(ViewerPass::Count)) {
    loadScene(scene, buildSceneArrays(ctx, scene, Accel::Bvh, bvhBuild_), torchIsLastLight);
    frameUniforms_ = gpu::Buffer(ctx, sizeof(shader::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                 gpu::MemoryKind::HostVisible);
    viewerUniforms_ = gpu::Buffer(ctx, sizeof(shader::ViewerUniforms), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                  gpu::MemoryKind::HostVisible);
    counters_ = makeRayCounters(ctx);
    heatCounters_ = gpu::Buffer(ctx, sizeof(shader::HeatCounters),
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                gpu::MemoryKind::HostVisible);
    std::memset(heatCounters_.mapped(), 0, sizeof(shader::HeatCounters));
    std::memset(frameUniforms_.mapped(), 0, sizeof(shader::FrameUniforms));
    std::memset(viewerUniforms_.mapped(), 0, sizeof(shader::ViewerUniforms));
}

InteractiveRenderer::~InteractiveRenderer() = default;

void InteractiveRenderer::loadScene(const Scene& scene, SceneArrays arrays, bool torchIsLastLight) {
    arrays_ = std::move(arrays);
    background_ = scene.background;
    environment_ = Environment{std::nullopt, std::nullopt, scene.environment.intensity,
                               scene.environment.rotationDegrees};
    gpuScene_ = std::make_unique<GpuScene>(ctx_, commands_, arrays_);
    instancesPrev_ = gpu::uploadStorageBuffer<shader::Instance>(ctx_, commands_, arrays_.instances);
    // The previous frame's instances (for instancesPrev_), then what a move uploads.
    instanceStaging_ = gpu::Buffer(ctx_, arrays_.instances.size() * sizeof(shader::Instance) + instanceUploadBytes(arrays_),
                                   VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryKind::HostVisible);
    lastFrameInstances_ = arrays_.instances;
    prevMatchesCurrent_ = true;
    // Lights without power are dropped on conversion, but the torch has power, so it stays last.
    torchLight_.reset();
    if (torchIsLastLight && !arrays_.punctual.empty() && !scene.lights.empty() && scene.lights.back().intensity > 0)
        torchLight_ = static_cast<std::uint32_t>(arrays_.punctual.size() - 1);
}

void InteractiveRenderer::rebuildScene(const Scene& scene, bool torchIsLastLight) {
    SceneArrays arrays = buildSceneArrays(ctx_, scene, Accel::Bvh, bvhBuild_);  // throws before anything is torn down
    PN_VK(vkDeviceWaitIdle(ctx_.device()));         // the last frame may still read the old buffers
    gpuScene_.reset();
    loadScene(scene, std::move(arrays), torchIsLastLight);
    if (width_ > 0) createPasses();
    historyValid_ = false;
    previousFrame_.reset();
}

void InteractiveRenderer::setMaterial(std::uint32_t index, const Material& material) {
    PN_CHECK(index < arrays_.materials.size());
    shader::Material gm = toGpuMaterial(material);
    const shader::Material& old = arrays_.materials[index];
    PN_CHECK(gm.emission.x == old.emission.x && gm.emission.y == old.emission.y && gm.emission.z == old.emission.z);
    arrays_.materials[index] = gm;
    PN_VK(vkDeviceWaitIdle(ctx_.device()));
    commands_.run([&](VkCommandBuffer cmd) {
        vkCmdUpdateBuffer(cmd, gpuScene_->materials.get(), VkDeviceSize(index) * sizeof(gm), sizeof(gm), &gm);
    });
    // A material now glass, metal or coated needs kernels made for that: the ones in use may have
    // left its code out (and the last such material turned matte lets the kernels leave it out).
    if (kernelSpecAfter(spec_, arrays_, kEditMaterials) != spec_) createPasses();
    historyValid_ = false;
    stillGBuffer_[0] = stillGBuffer_[1] = false;  // the albedo changed
}

void InteractiveRenderer::setUnsampledEmission(std::uint32_t index, Vec3 emission) {
    PN_CHECK(index < arrays_.materials.size());
    arrays_.materials[index].emission = emission;
    pendingMaterials_.push_back(index);
    historyValid_ = false;
}

void InteractiveRenderer::setInstanceTransforms(const Scene& scene) { moveInstances(arrays_, scene); }

void InteractiveRenderer::uploadInstances(VkCommandBuffer cmd, bool moved) {
    const std::vector<shader::Instance>& now = arrays_.instances;
    if (now.empty() || (!moved && prevMatchesCurrent_)) return;
    // The previous frame's placement while it moved; once it stops, the current one again.
    const bool objectMotion = moved && objectMotionVectors_ && historyValid_;
    const std::vector<shader::Instance>& prev = objectMotion ? lastFrameInstances_ : now;
    const VkDeviceSize instanceBytes = now.size() * sizeof(shader::Instance);
    std::memcpy(instanceStaging_.mapped(), prev.data(), instanceBytes);
    const VkBufferCopy toPrev{0, 0, instanceBytes};
    vkCmdCopyBuffer(cmd, instanceStaging_.get(), instancesPrev_.get(), 1, &toPrev);
    if (moved) {
        recordInstanceUpload(cmd, arrays_, *gpuScene_, instanceStaging_, instanceBytes);
        lastFrameInstances_ = now;
        boxesDepth_.reset();  // the overlay's boxes include the top level
    }
    prevMatchesCurrent_ = !objectMotion;
}

void InteractiveRenderer::resize(std::uint32_t width, std::uint32_t height) {
    if (width == width_ && height == height_) return;
    RenderSettings check;
    check.width = width;
    check.height = height;
    validateSettings(check);
    PN_VK(vkDeviceWaitIdle(ctx_.device()));  // the old buffers may still be in use by the last frame
    width_ = width;
    height_ = height;
    const VkDeviceSize pixels = VkDeviceSize(width) * height;
    auto pixelBuffer = [&](VkDeviceSize bytesPerPixel) {
        return gpu::Buffer(ctx_, pixels * bytesPerPixel, kPixelUsage, gpu::MemoryKind::DeviceLocal);
    };
    accumulation_ = pixelBuffer(sizeof(Vec4));
    gbufferA_ = pixelBuffer(sizeof(shader::GBufferTexel));
    gbufferB_ = pixelBuffer(sizeof(shader::GBufferTexel));
    historyA_ = pixelBuffer(sizeof(shader::HistoryTexel));
    historyB_ = pixelBuffer(sizeof(shader::HistoryTexel));
    filterA_ = pixelBuffer(sizeof(Vec4));
    filterB_ = pixelBuffer(sizeof(Vec4));
    guide_ = pixelBuffer(PN_DENOISE_GUIDE_BYTES);
    display_ = pixelBuffer(sizeof(std::uint32_t));
    pixelEstimates_ = pixelBuffer(sizeof(Vec4));
    historyIn_ = &historyA_;
    historyOut_ = &historyB_;
    // Everything starts defined, so no pass ever reads uninitialised memory.
    commands_.run([&](VkCommandBuffer cmd) {
        for (gpu::Buffer* b : {&accumulation_, &gbufferA_, &gbufferB_, &historyA_, &historyB_, &filterA_, &filterB_, &guide_,
                               &display_, &pixelEstimates_})
            vkCmdFillBuffer(cmd, b->get(), 0, VK_WHOLE_SIZE, 0);
    });
    createPasses();
    historyValid_ = false;
    previousFrame_.reset();
}

KernelSpec InteractiveRenderer::sceneKernelSpec() const {
    return penumbra::kernelSpec(arrays_, cullBackfaces_, frameStatistics_);
}

void InteractiveRenderer::setFrameStatistics(bool on) {
    if (on == frameStatistics_) return;
    frameStatistics_ = on;
    if (trace_) createPasses();  // the image stays the same: history is kept
}

void InteractiveRenderer::setCullBackfaces(bool on) {
    if (on == cullBackfaces_) return;
    cullBackfaces_ = on;
    if (trace_) createPasses();
    historyValid_ = false;
}

void InteractiveRenderer::createPasses() {
    stillGBuffer_[0] = stillGBuffer_[1] = false;  // new buffers, or a new scene in them
    spec_ = sceneKernelSpec();
    trace_ = std::make_unique<TracePass>(ctx_, *gpuScene_, frameUniforms_, accumulation_, counters_, spec_);
    trace_->setReplacesAccumulation(true);  // one pass per frame: no clear before it
    trace_->setPixelEstimates(&pixelEstimates_);  // the temporal pass's, for the shadow-ray roulette
    auto gbufferPass = [&](const gpu::Buffer& out) {
        return std::make_unique<GBufferPass>(ctx_, *gpuScene_, frameUniforms_, viewerUniforms_, out, spec_,
                                             &instancesPrev_);
    };
    gbufferPassA_ = gbufferPass(gbufferA_);
    gbufferPassB_ = gbufferPass(gbufferB_);
    auto temporal = [&](const gpu::Buffer& in, const gpu::Buffer& gbufferIn, const gpu::Buffer& out,
                        const gpu::Buffer& gbufferOut) {
        return std::make_unique<TemporalPass>(
            ctx_, TemporalBuffers{&frameUniforms_, &viewerUniforms_, &accumulation_, &gbufferOut, &gbufferIn, &in,
                                  &out, &filterA_, &guide_, &pixelEstimates_});
    };
    temporalAB_ = temporal(historyA_, gbufferA_, historyB_, gbufferB_);
    temporalBA_ = temporal(historyB_, gbufferB_, historyA_, gbufferA_);
    // A frame that writes history and G-buffer B (temporalAB_) denoises with B's.
    auto denoise = [&](const gpu::Buffer& gbuffer, const gpu::Buffer& history) {
        return std::make_unique<DenoisePass>(ctx_, frameUniforms_, viewerUniforms_, gbuffer, guide_, history, filterA_,
                                             filterB_, &display_);
    };
    denoiseA_ = denoise(gbufferA_, historyA_);
    denoiseB_ = denoise(gbufferB_, historyB_);
    tonemapA_ = std::make_unique<TonemapPass>(ctx_, frameUniforms_, viewerUniforms_, historyA_, filterB_, gbufferA_, display_);
    tonemapB_ = std::make_unique<TonemapPass>(ctx_, frameUniforms_, viewerUniforms_, historyB_, filterB_, gbufferB_, display_);
    heatmap_ = std::make_unique<HeatmapPass>(ctx_, *gpuScene_, frameUniforms_, viewerUniforms_, filterB_, heatCounters_);
    boxes_ = std::make_unique<BoxOverlayPass>(ctx_, frameUniforms_, viewerUniforms_, display_);
    boxesDepth_.reset();
}

void InteractiveRenderer::record(VkCommandBuffer cmd, const Camera& camera, const ViewSettings& s) {
    PN_CHECK(width_ > 0 && height_ > 0);
    trace_->reserve(width_, height_, s.samplesPerFrame);  // before this frame records anything
    startHistory(s);
    shader::FrameUniforms f = frameUniforms(camera, s);
    // An animated texture that turned to its next frame changed the image: blend history as for a
    // moving camera. Between its ticks the image holds still and the mean keeps converging.
    const bool animating = previousFrame_ && animationTicked(arrays_.textures, previousFrame_->time, f.time);
    // Moved instances change the image too (and their light and shadows move with them).
    const bool instancesMoved =
        !arrays_.instances.empty() && std::memcmp(lastFrameInstances_.data(), arrays_.instances.data(),
                                                  arrays_.instances.size() * sizeof(shader::Instance)) != 0;
    // At rest since the frame before too: the rest tree's flat walk (render/rest_tree.h). The frame
    // an instance comes to rest still walks two levels, so its last step has its motion vectors.
    if (!instancesMoved && atRest(arrays_)) walkRestTree(f, arrays_);
    const bool moved = previousFrame_ && (!sameCamera(*previousFrame_, f) || animating || instancesMoved);
    if (s.preview && moved) return recordPreview(cmd, camera, s, f, instancesMoved);
    // A still view whose G-buffers both hold it reuses them (recordGBuffer): the temporal pass is
    // told, so it neither compares them nor writes the denoiser's guide again.
    if (moved) stillGBuffer_[0] = stillGBuffer_[1] = false;
    const bool reuseGBuffer = stillGBuffer_[0] && stillGBuffer_[1];
    shader::ViewerUniforms v = viewerUniforms(s, f, moved);
    v.gbufferReused = reuseGBuffer ? 1u : 0u;
    const bool heat = isHeatView(s.debug);
    std::memcpy(frameUniforms_.mapped(), &f, sizeof(f));
    std::memcpy(viewerUniforms_.mapped(), &v, sizeof(v));
    clearRayCounters(counters_);
    heatFrame_ = heat;

    timer_.reset();
    recorded_ = 0;
    timer_.begin(cmd, std::uint32_t(ViewerPass::Frame));
    recordUploads(cmd, camera, s, instancesMoved, heat);
    recordPasses(cmd, s, heat, v.denoise != 0, moved, reuseGBuffer);
    if (s.debug == DebugView::BvhBoxes) recordBoxOverlay(cmd, s);
    timer_.end(cmd, std::uint32_t(ViewerPass::Frame));
    recorded_ |= 1u << std::uint32_t(ViewerPass::Frame);

    previousFrame_ = f;
    historyValid_ = true;
    ++frameIndex_;
    stats_.samplesPerPixel = frameIndex_ * s.samplesPerFrame;
}

void InteractiveRenderer::recordPreview(VkCommandBuffer cmd, const Camera& camera, const ViewSettings& s,
                                        shader::FrameUniforms f, bool instancesMoved) {
    shader::ViewerUniforms v = viewerUniforms(s, f, true);
    v.debugMode = PN_DEBUG_PREVIEW;
    v.debugOpacity = 1.0f;
    v.debugInset = 0u;
    v.denoise = 0u;
    std::memcpy(frameUniforms_.mapped(), &f, sizeof(f));
    std::memcpy(viewerUniforms_.mapped(), &v, sizeof(v));
    clearRayCounters(counters_);
    heatFrame_ = false;
    timer_.reset();
    recorded_ = 0;
    timer_.begin(cmd, std::uint32_t(ViewerPass::Frame));
    recordUploads(cmd, camera, s, instancesMoved, false);
    const bool toB = historyIn_ == &historyA_;
    recordGBuffer(cmd, toB, true, false);
    gpu::computeBarrier(cmd);
    TonemapPass& tonemap = toB ? *tonemapB_ : *tonemapA_;
    tonemap.setFiltered(filterB_);
    timed(cmd, ViewerPass::Tonemap, [&] { tonemap.record(cmd, width_, height_); });
    gpu::computeBarrier(cmd);
    timer_.end(cmd, std::uint32_t(ViewerPass::Frame));
    recorded_ |= 1u << std::uint32_t(ViewerPass::Frame);
    denoised_ = nullptr;
    stats_.tonemapInDenoiser = false;
    previousFrame_ = f;
    // Nothing was traced: the first still frame starts the path-traced mean afresh.
    historyValid_ = false;
    frameIndex_ = 0;
    stats_.samplesPerPixel = 0;
}

void InteractiveRenderer::startHistory(const ViewSettings& s) {
    if (previousSettings_ && changesTheImage(*previousSettings_, s)) historyValid_ = false;
    if (!s.temporal) historyValid_ = false;
    previousSettings_ = s;
    if (!historyValid_) frameIndex_ = 0;
    if (frameIndex_ > 0) std::swap(historyIn_, historyOut_);
}

shader::FrameUniforms InteractiveRenderer::frameUniforms(const Camera& camera, const ViewSettings& s) const {
    RenderSettings rs;
    rs.width = width_;
    rs.height = height_;
    rs.samplesPerPass = s.samplesPerFrame;
    rs.maxBounces = s.maxBounces;
    rs.rouletteStart = s.rouletteStart;
    rs.shadowRouletteShare = s.shadowRouletteShare;
    rs.pixelJitter = s.antiAliasing;
    rs.seed = seed_;
    rs.time = s.time;
    rs.textureSaturation = s.textureSaturation;
    rs.renderDistance = s.renderDistance;
    Camera lens = camera;
    lens.apertureRadius = s.apertureRadius;
    lens.focusDistance = s.focusDistance;
    shader::FrameUniforms f = makeSceneFrameUniforms(lens, background_, environment_, rs, *gpuScene_);
    // The torch is the last punctual light, so switching it off is leaving it out of the count.
    if (torchLight_ && !s.torch) --f.punctualCount;
    return f;
}

shader::ViewerUniforms InteractiveRenderer::viewerUniforms(const ViewSettings& s, const shader::FrameUniforms& f,
                                                           bool moved) const {
    const DebugView shown = shownDebugView(s);
    shader::ViewerUniforms v{};
    setPreviousCamera(v, previousFrame_ ? *previousFrame_ : f);
    v.historyValid = historyValid_ ? 1u : 0u;
    v.cameraMoved = moved ? 1u : 0u;
    v.exposure = s.exposure;
    v.toneMapper = std::uint32_t(s.toneMapper);
    v.debugMode = std::uint32_t(shown);
    v.samplesPerFrame = s.samplesPerFrame;
    v.clampSigma = s.clampSigma;
    v.depthTolerance = 0.1f;
    v.normalTolerance = 0.9f;
    v.maxHistory = s.maxHistory;
    v.sigmaLuminance = s.sigmaLuminance;
    v.sigmaNormal = s.sigmaNormal;
    v.sigmaDepth = s.sigmaDepth;
    const bool heat = isHeatView(s.debug);
    v.heatMax = heat ? float(heatScaleMax(s.debug, *static_cast<const shader::HeatCounters*>(heatCounters_.mapped())))
                     : float(frameIndex_ + 1) * float(s.samplesPerFrame);
    v.debugOpacity = std::clamp(s.debugOpacity, 0.0f, 1.0f);
    v.debugInset = s.debugInset ? 1u : 0u;
    // The image shows under a see-through or small debug view; the heat counts use the buffer
    // the denoiser writes, so under a heat map the image is not denoised.
    const bool imageShown = shown == DebugView::None || v.debugOpacity < 1.0f || s.debugInset;
    v.denoise = s.denoise && s.denoiseIterations > 0 && imageShown && !heat ? 1u : 0u;
    return v;
}

void InteractiveRenderer::recordUploads(VkCommandBuffer cmd, const Camera& camera, const ViewSettings& s,
                                        bool instancesMoved, bool heat) {
    if (torchLight_ && s.torch) {
        // attachTorch's placement: 15 cm below the eye.
        shader::PunctualLight light = arrays_.punctual[*torchLight_];
        light.position = camera.position - normalize(camera.up) * 0.15f;
        light.intensity = s.torchColor * s.torchIntensity;
        light.range = s.torchRange;
        vkCmdUpdateBuffer(cmd, gpuScene_->punctual.get(), VkDeviceSize(*torchLight_) * sizeof(light), sizeof(light),
                          &light);
    }
    uploadInstances(cmd, instancesMoved);
    for (std::uint32_t index : pendingMaterials_)
        vkCmdUpdateBuffer(cmd, gpuScene_->materials.get(), VkDeviceSize(index) * sizeof(shader::Material),
                          sizeof(shader::Material), &arrays_.materials[index]);
    pendingMaterials_.clear();
    if (heat) vkCmdFillBuffer(cmd, heatCounters_.get(), 0, VK_WHOLE_SIZE, 0);
    transferToComputeBarrier(cmd);
}

void InteractiveRenderer::recordGBuffer(VkCommandBuffer cmd, bool toB, bool moved, bool reuse) {
    stats_.gbufferSkipped = reuse;
    if (reuse) return;
    timed(cmd, ViewerPass::GBuffer, [&] { (toB ? gbufferPassB_ : gbufferPassA_)->record(cmd, width_, height_); });
    stillGBuffer_[toB ? 1 : 0] = !moved;
}

void InteractiveRenderer::recordPasses(VkCommandBuffer cmd, const ViewSettings& s, bool heat, bool denoise, bool moved,
                                       bool reuseGBuffer) {
    // This frame writes the letter last frame read (startHistory swapped them).
    const bool toB = historyIn_ == &historyA_;
    trace_->setSharesCameraRays(s.shareCameraRays);
    timed(cmd, ViewerPass::Trace,
          [&] { trace_->record(cmd, width_, height_, s.samplesPerFrame, tracedFrames_++, s.maxBounces, true); });
    recordGBuffer(cmd, toB, moved, reuseGBuffer);
    if (heat) timed(cmd, ViewerPass::Heatmap, [&] { heatmap_->record(cmd, width_, height_); });
    gpu::computeBarrier(cmd);
    timed(cmd, ViewerPass::Temporal, [&] { (toB ? temporalAB_ : temporalBA_)->record(cmd, width_, height_); });
    gpu::computeBarrier(cmd);
    TonemapPass& tonemap = toB ? *tonemapB_ : *tonemapA_;
    // With nothing drawn over the image, the denoiser's last pass writes the display itself.
    const bool denoiserDisplays = denoise && shownDebugView(s) == DebugView::None;
    stats_.tonemapInDenoiser = denoiserDisplays;
    if (denoise) {
        const DenoisePass& filter = toB ? *denoiseB_ : *denoiseA_;
        timed(cmd, ViewerPass::Denoise,
              [&] { filter.record(cmd, width_, height_, s.denoiseIterations, denoiserDisplays, !s.denoiseConverges); });
        denoised_ = &filter.output(s.denoiseIterations);
        tonemap.setFiltered(*denoised_);
    } else {
        denoised_ = nullptr;
        tonemap.setFiltered(filterB_);  // the heat map's counts, when it ran
    }
    if (!denoiserDisplays) {
        timed(cmd, ViewerPass::Tonemap, [&] { tonemap.record(cmd, width_, height_); });
        gpu::computeBarrier(cmd);
    }
}

std::vector<gpu::PipelineStatistic> InteractiveRenderer::imageStatistics() const {
    std::vector<gpu::PipelineStatistic> out = temporalAB_->statistics();
    for (gpu::PipelineStatistic& s : denoiseA_->statistics()) out.push_back(std::move(s));
    return out;
}

void InteractiveRenderer::recordBoxOverlay(VkCommandBuffer cmd, const ViewSettings& s) {
    if (boxesDepth_ != s.boxDepth) {  // the previous frame has finished, so its boxes are free
        boxes_->setBoxes(bvh::nodesAtDepth(arrays_.nodes, s.boxDepth, PN_MAX_OVERLAY_BOXES));
        boxesDepth_ = s.boxDepth;
    }
    timed(cmd, ViewerPass::Boxes, [&] { boxes_->record(cmd, width_, height_, s.boxLineWidth); });
    gpu::computeBarrier(cmd);
}

void InteractiveRenderer::finishFrame() {
    for (std::uint32_t p = 0; p < std::uint32_t(ViewerPass::Count); ++p)
        stats_.passMilliseconds[p] = (recorded_ >> p) & 1u ? timer_.milliseconds(p) : 0.0;
    const RayCounts counts = sumRayCounters(counters_);
    const double traceSeconds = stats_.passMilliseconds[std::size_t(ViewerPass::Trace)] * 1e-3;
    stats_.rays = counts.closestRays + counts.shadowRays;
    stats_.closestRays = counts.closestRays;
    stats_.shadowRays = counts.shadowRays;
    stats_.primitivesTested = counts.primitivesTested;
    stats_.closestHits = counts.closestHits;
    stats_.shadowBlocked = counts.shadowBlocked;
    stats_.frameStatistics = spec_.hasOption(PN_OPTION_FRAME_STATS);
    stats_.raysPerSecond = traceSeconds > 0 ? double(stats_.rays) / traceSeconds : 0.0;
    if (heatFrame_) {
        const auto* heat = static_cast<const shader::HeatCounters*>(heatCounters_.mapped());
        stats_.heatMaxNodes = heat->maxNodes;
        stats_.heatMaxTriangles = heat->maxTris;
        stats_.heatMaxLeafDepth = heat->maxLeafDepth;
        stats_.heatMaxLeafTriangles = heat->maxLeafTris;
    }
}

}  // namespace penumbra
