#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cstring>

#include "core/error.h"
#include "render/frame_uniforms.h"
#include "render/instance_arrays.h"
#include "render/instance_upload.h"
#include "render/kernel_features.h"
#include "render/ray_counters.h"
#include "render/rest_tree.h"

namespace penumbra {

Renderer::Renderer(const gpu::Context& ctx, const Scene& scene, const RenderSettings& settings)
    : ctx_(ctx), settings_(settings), arrays_(buildSceneArrays(ctx, scene, settings.accel, settings.bvhBuild)), commands_(ctx), timer_(ctx, 1) {
    validateSettings(settings_);
    gpuScene_ = std::make_unique<GpuScene>(ctx, commands_, arrays_);
    background_ = scene.background;
    environment_ = Environment{std::nullopt, std::nullopt, scene.environment.intensity, scene.environment.rotationDegrees};
    frameUniforms_ = gpu::Buffer(ctx, sizeof(shader::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                 gpu::MemoryKind::HostVisible);
    const shader::FrameUniforms frame = sceneUniforms(scene.camera);
    std::memcpy(frameUniforms_.mapped(), &frame, sizeof(frame));

    const VkDeviceSize pixels = VkDeviceSize(settings_.width) * settings_.height;
    accumulation_ = gpu::Buffer(ctx, pixels * sizeof(Vec4),
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                    VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                gpu::MemoryKind::DeviceLocal);
    counters_ = makeRayCounters(ctx);
    commands_.run([&](VkCommandBuffer cmd) { vkCmdFillBuffer(cmd, accumulation_.get(), 0, VK_WHOLE_SIZE, 0); });
    activeMask_ = gpu::Buffer(ctx, pixels * sizeof(std::uint32_t),
                              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              gpu::MemoryKind::DeviceLocal);
    spec_ = penumbra::kernelSpec(arrays_, settings_.cullBackfaces);
    makeTracePass();
}

shader::FrameUniforms Renderer::sceneUniforms(const Camera& camera) const {
    shader::FrameUniforms f = makeSceneFrameUniforms(camera, background_, environment_, settings_, *gpuScene_);
    if (atRest(arrays_)) walkRestTree(f, arrays_);  // every instance where it was modelled
    return f;
}

void Renderer::makeTracePass() {
    trace_ = std::make_unique<TracePass>(ctx_, *gpuScene_, frameUniforms_, accumulation_, counters_, spec_, &activeMask_);
    trace_->setPathBudget(settings_.pathsPerDispatch);
    trace_->setSharesCameraRays(settings_.shareCameraRays);
    trace_->reserve(settings_.width, settings_.height, settings_.samplesPerPass);
}

void Renderer::setFrameStatistics(bool on) {
    const KernelSpec spec = spec_.withOption(PN_OPTION_FRAME_STATS, on);
    if (spec == spec_) return;
    spec_ = spec;
    makeTracePass();
}

Renderer::~Renderer() = default;

void Renderer::setUnsampledEmission(std::uint32_t material, Vec3 emission) {
    PN_CHECK(material < arrays_.materials.size());
    shader::Material& m = arrays_.materials[material];
    m.emission = emission;
    // renderPasses starts with a barrier that makes transfer writes visible to the trace.
    commands_.run([&](VkCommandBuffer cmd) {
        vkCmdUpdateBuffer(cmd, gpuScene_->materials.get(), VkDeviceSize(material) * sizeof(shader::Material),
                          sizeof(shader::Material), &m);
    });
}

void Renderer::setMaterial(std::uint32_t index, const Material& material) {
    PN_CHECK(index < arrays_.materials.size());
    const shader::Material gm = toGpuMaterial(material);
    const shader::Material& old = arrays_.materials[index];
    PN_CHECK(gm.emission.x == old.emission.x && gm.emission.y == old.emission.y && gm.emission.z == old.emission.z);
    arrays_.materials[index] = gm;
    commands_.run([&](VkCommandBuffer cmd) {
        vkCmdUpdateBuffer(cmd, gpuScene_->materials.get(), VkDeviceSize(index) * sizeof(gm), sizeof(gm), &gm);
    });
    // A material that now needs code the kernels left out (or the last one that needed it) brings
    // new kernels (render/kernel_features.h).
    const KernelSpec spec = kernelSpecAfter(spec_, arrays_, kEditMaterials);
    if (spec != spec_) {
        spec_ = spec;
        makeTracePass();
    }
}

void Renderer::setInstanceTransforms(const Scene& scene) {
    if (!moveInstances(arrays_, scene)) return;
    if (instanceStaging_.get() == VK_NULL_HANDLE)
        instanceStaging_ = gpu::Buffer(ctx_, instanceUploadBytes(arrays_), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                       gpu::MemoryKind::HostVisible);
    // renderPasses starts with a barrier that makes transfer writes visible to the trace.
    commands_.run([&](VkCommandBuffer cmd) {
        gpu::computeBarrier(cmd);  // passes still reading the top level finish first
        recordInstanceUpload(cmd, arrays_, *gpuScene_, instanceStaging_, 0);
    });
}

double Renderer::renderPasses(std::uint32_t passes, bool countRays, bool masked) {
    timer_.reset();
    commands_.run([&](VkCommandBuffer cmd) {
        // The fill that cleared the buffer, and earlier passes, must land before we add to it.
        gpu::computeBarrier(cmd);
        timer_.begin(cmd, 0);
        for (std::uint32_t i = 0; i < passes; ++i) {
            trace_->record(cmd, settings_.width, settings_.height, settings_.samplesPerPass, passesDone_ + i,
                           settings_.maxBounces, countRays, masked);
            gpu::computeBarrier(cmd);
        }
        timer_.end(cmd, 0);
    });
    passesDone_ += passes;
    stats_.samplesPerPixel = passesDone_ * settings_.samplesPerPass;
    const double ms = timer_.milliseconds(0);
    stats_.gpuMilliseconds += std::max(0.0, ms);
    const RayCounts counts = sumRayCounters(counters_);
    stats_.closestRays += counts.closestRays;
    stats_.shadowRays += counts.shadowRays;
    stats_.invalidSamples += counts.invalidSamples;
    stats_.primitivesTested += counts.primitivesTested;
    stats_.closestHits += counts.closestHits;
    stats_.shadowBlocked += counts.shadowBlocked;
    clearRayCounters(counters_);
    return ms;
}

void Renderer::render(const std::function<void(std::uint32_t)>& onProgress) {
    const std::uint32_t totalPasses = (settings_.samplesPerPixel + settings_.samplesPerPass - 1) / settings_.samplesPerPass;
    // Submissions of about a tenth of a second: responsive progress, little per-submit overhead,
    // and no single submission long enough to trip a driver watchdog. The ray counters are 32-bit
    // per submission, which this also keeps far from overflowing.
    std::uint32_t batch = 1;
    while (passesDone_ < totalPasses) {
        std::uint32_t n = std::min(batch, totalPasses - passesDone_);
        auto start = std::chrono::steady_clock::now();
        renderPasses(n);
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        double perPass = seconds / n;
        batch = perPass > 0 ? std::clamp<std::uint32_t>(std::uint32_t(0.1 / perPass), 1, 32) : 32;
        if (onProgress) onProgress(stats_.samplesPerPixel);
    }
}

void Renderer::restart(const Camera& camera) {
    const shader::FrameUniforms frame = sceneUniforms(camera);
    std::memcpy(frameUniforms_.mapped(), &frame, sizeof(frame));
    commands_.run([&](VkCommandBuffer cmd) { vkCmdFillBuffer(cmd, accumulation_.get(), 0, VK_WHOLE_SIZE, 0); });
    passesDone_ = 0;
    stats_ = {};
}

void Renderer::restart(const Camera& camera, float time) {
    settings_.time = time;
    restart(camera);
}

void Renderer::setActiveMask(std::span<const std::uint32_t> mask) {
    PN_CHECK(mask.size() == std::size_t(settings_.width) * settings_.height);
    gpu::uploadToBuffer(ctx_, commands_, activeMask_, mask.data(), mask.size_bytes());
}

std::vector<Vec4> Renderer::takeAccumulation() {
    std::vector<Vec4> sums = accumulation();
    commands_.run([&](VkCommandBuffer cmd) {
        gpu::computeBarrier(cmd);
        vkCmdFillBuffer(cmd, accumulation_.get(), 0, VK_WHOLE_SIZE, 0);
    });
    return sums;
}

void Renderer::loadAccumulation(std::span<const Vec4> sums) {
    PN_CHECK(sums.size() == std::size_t(settings_.width) * settings_.height);
    gpu::uploadToBuffer(ctx_, commands_, accumulation_, sums.data(), sums.size_bytes());
}

void Renderer::setPassesDone(std::uint32_t passes) {
    passesDone_ = passes;
    stats_.samplesPerPixel = passesDone_ * settings_.samplesPerPass;
}

std::vector<Vec4> Renderer::accumulation() {
    return gpu::downloadBuffer<Vec4>(ctx_, commands_, accumulation_, std::size_t(settings_.width) * settings_.height);
}

ImageRgb Renderer::image() {
    std::vector<Vec4> sums = accumulation();
    ImageRgb img(static_cast<int>(settings_.width), static_cast<int>(settings_.height));
    const float inv = stats_.samplesPerPixel ? 1.0f / float(stats_.samplesPerPixel) : 0.0f;
    for (std::size_t i = 0; i < sums.size(); ++i) img.pixels[i] = Vec3{sums[i].x, sums[i].y, sums[i].z} * inv;
    return img;
}

}  // namespace penumbra
