#include "render/passes/wavefront_pass.h"

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <string>

#include "core/error.h"
#include "core/median.h"
#include "gpu/check.h"
#include "gpu/commands.h"
#include "gpu/limits.h"
#include "render/tuning.h"

namespace penumbra {

namespace {

constexpr std::uint32_t kWorkingBindings[] = {PN_BINDING_WAVE_PATHS, PN_BINDING_WAVE_HITS, PN_BINDING_WAVE_SHADOWS,
                                              PN_BINDING_WAVE_QUEUES, PN_BINDING_WAVE_CONTROL};

std::uint32_t groupsFor(std::uint64_t items) { return std::uint32_t((items + PN_WAVE_GROUP - 1) / PN_WAVE_GROUP); }

enum Stage : std::uint32_t { kStart, kExtend, kShade, kShadow, kTail, kFinish, kStageCount };
constexpr const char* kStageNames[kStageCount] = {"start", "extend", "shade", "shadow", "tail", "finish"};

}  // namespace

WavefrontPass::WavefrontPass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
                             const TraceOutputs& outputs, KernelSpec spec)
    : ctx_(ctx) {
    const std::vector<std::uint32_t> extra(std::begin(kWorkingBindings), std::end(kWorkingBindings));
    auto make = [&](const char* shader, std::uint32_t camera = PN_CAMERA_FROM_QUEUE) {
        return makeTracePipeline(ctx, shader, scene, frameUniforms, outputs, extra, spec, camera);
    };
    start_ = make("wave_start");
    extend_ = make("wave_extend");
    shade_ = make("wave_shade");
    extendCamera_ = make("wave_extend", PN_CAMERA_IN_PLACE);
    shadeCamera_ = make("wave_shade", PN_CAMERA_IN_PLACE);
    shadow_ = make("wave_shadow");
    tail_ = make("wave_tail");
    finish_ = make("wave_finish");
    const gpu::BindingSpec controlOnly[] = {{PN_BINDING_WAVE_CONTROL, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
    args_ = std::make_unique<gpu::ComputePipeline>(ctx, "wave_args", controlOnly, sizeof(shader::PassPush));
    control_ = gpu::Buffer(ctx, sizeof(shader::WaveControl),
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                               VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                           gpu::MemoryKind::DeviceLocal);
    args_->bind(PN_BINDING_WAVE_CONTROL, control_);
    reserve(PN_WAVE_GROUP);
    tailPaths_ = renderTuning().waveTailPaths;
    if (renderTuning().waveStageTimes) stageTimes_ = std::make_unique<StageTimes>(ctx);
}

template <typename Dispatch>
void WavefrontPass::timed(VkCommandBuffer cmd, std::uint32_t stage, std::uint32_t round, Dispatch&& dispatch) {
    if (!stageTimes_ || stageTimes_->sections.size() >= StageTimes::kSections) {
        dispatch();
        return;
    }
    const auto section = std::uint32_t(stageTimes_->sections.size());
    stageTimes_->sections.push_back({stage, round});
    gpu::computeBarrier(cmd);  // the step runs alone
    stageTimes_->timer.begin(cmd, section);
    dispatch();
    stageTimes_->timer.end(cmd, section);
}

void WavefrontPass::collectStageTimes(VkCommandBuffer cmd) {
    if (!stageTimes_) return;
    StageTimes& st = *stageTimes_;
    double sums[kStageCount] = {};
    std::map<std::string, double> perRound;
    bool landed = !st.sections.empty();
    for (std::uint32_t i = 0; i < st.sections.size() && landed; ++i) {
        const std::optional<double> ms = st.timer.millisecondsIfReady(i);
        landed = ms.has_value();
        if (!landed) break;
        const StageTimes::Section s = st.sections[i];
        sums[s.stage] += *ms;
        perRound[std::string(kStageNames[s.stage]) + ".b" + std::to_string(s.round)] += *ms;
    }
    if (landed) {
        for (std::uint32_t k = 0; k < kStageCount; ++k) st.perPass[kStageNames[k]].push_back(sums[k]);
        for (const auto& [name, ms] : perRound) st.perPass[name].push_back(ms);
    }
    st.sections.clear();
    st.timer.reset(cmd);
}

std::map<std::string, double> WavefrontPass::stageMilliseconds() const {
    std::map<std::string, double> out;
    if (stageTimes_)
        for (const auto& [name, values] : stageTimes_->perPass) out[name] = median(values);
    return out;
}

std::uint64_t WavefrontPass::maxSlots(const gpu::Context& ctx) {
    constexpr std::uint64_t pathBytes = PN_WAVE_PATH_VEC4S * 16;
    constexpr std::uint64_t slotBytes = pathBytes + 2 * 16 + PN_WAVE_SHADOW_VEC4S * 16 + 2 * sizeof(std::uint32_t);
    const gpu::MemoryLimits limits = gpu::memoryLimits(ctx);
    const std::uint64_t slots = std::min(limits.maxStorageBufferRange / pathBytes, limits.deviceLocalBytes / 4 / slotBytes);
    return std::max<std::uint64_t>(slots / PN_WAVE_GROUP * PN_WAVE_GROUP, PN_WAVE_GROUP);
}

void WavefrontPass::reserve(std::uint64_t slots) {
    if (slots <= capacity_) return;
    if (capacity_ != 0) PN_VK(vkDeviceWaitIdle(ctx_.device()));  // the old buffers may still be in use
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    const VkDeviceSize n = slots;
    paths_ = gpu::Buffer(ctx_, n * PN_WAVE_PATH_VEC4S * 16, storage, gpu::MemoryKind::DeviceLocal);
    hits_ = gpu::Buffer(ctx_, n * 2 * 16, storage, gpu::MemoryKind::DeviceLocal);  // hits, then instances
    shadows_ = gpu::Buffer(ctx_, n * PN_WAVE_SHADOW_VEC4S * 16, storage, gpu::MemoryKind::DeviceLocal);
    queues_ = gpu::Buffer(ctx_, n * 2 * sizeof(std::uint32_t), storage, gpu::MemoryKind::DeviceLocal);
    capacity_ = slots;
    bindWorkingBuffers();
}

void WavefrontPass::bindWorkingBuffers() {
    for (gpu::ComputePipeline* p : {start_.get(), extend_.get(), shade_.get(), extendCamera_.get(), shadeCamera_.get(),
                                    shadow_.get(), tail_.get(), finish_.get()}) {
        p->bind(PN_BINDING_WAVE_PATHS, paths_);
        p->bind(PN_BINDING_WAVE_HITS, hits_);
        p->bind(PN_BINDING_WAVE_SHADOWS, shadows_);
        p->bind(PN_BINDING_WAVE_QUEUES, queues_);
        p->bind(PN_BINDING_WAVE_CONTROL, control_);
    }
}

void WavefrontPass::beginPass(VkCommandBuffer cmd) { collectStageTimes(cmd); }

void WavefrontPass::record(VkCommandBuffer cmd, const TraceTile& tile, std::uint32_t width, std::uint32_t height,
                           std::uint32_t samplesPerPass, std::uint32_t passIndex, std::uint32_t maxBounces,
                           bool countRays, std::uint32_t traceMode) {
    const TraceTile inside = clipTile(tile, width, height);
    const std::uint32_t tileWidth = inside.width, tileHeight = inside.height;
    const std::uint64_t slots = std::uint64_t(tileWidth) * tileHeight * samplesPerPass;
    reserve(slots);
    // Every slot of an unmasked pass is live at bounce 0: unless the tail takes the pass from its
    // camera rays (it reads stored paths), bounce 0 makes the camera paths where it needs them and
    // the start step, its stores and its queue are skipped.
    const bool cameraInPlace = (traceMode & PN_TRACE_MASKED) == 0 && slots > tailPaths_;
    const std::uint32_t mode = traceMode | (cameraInPlace ? PN_WAVE_CAMERA_IN_PLACE : 0u);
    shader::PassPush push{passIndex,           mode, std::uint32_t(slots),
                          countRays ? 1u : 0u, tile.x, tile.y, tileWidth, tileHeight, std::uint32_t(capacity_), 0u, tailPaths_, 0u};
    vkCmdFillBuffer(cmd, control_.get(), 0, VK_WHOLE_SIZE, 0);
    gpu::computeBarrier(cmd);
    if (!cameraInPlace) {
        timed(cmd, kStart, 0, [&] { start_->dispatch(cmd, groupsFor(slots), 1, 1, &push); });
        gpu::computeBarrier(cmd);
    }
    // Bounce b traces the live paths' closest hits and shades them, while the shadow rays that
    // bounce b - 1 queued are traced alongside the closest hits (they touch disjoint state). Once
    // few paths are left, the args step hands them to the tail instead (extend and shade then
    // dispatch nothing), which runs beside the shadow rays too: it traces its own paths' pending
    // ones itself, first, and the shadow pass leaves them out.
    constexpr VkDeviceSize extendArgs = offsetof(shader::WaveControl, extendGroups);
    constexpr VkDeviceSize shadowArgs = offsetof(shader::WaveControl, shadowGroups);
    constexpr VkDeviceSize tailArgs = offsetof(shader::WaveControl, tailGroups);
    for (std::uint32_t b = 0; b <= maxBounces + 1; ++b) {
        push.waveBounce = b;
        args_->dispatch(cmd, 1, 1, 1, &push);
        gpu::indirectBarrier(cmd);
        // Bounce 0 of a pass that makes its camera paths in place runs the kernels made for it.
        const bool camera = b == 0 && cameraInPlace;
        const gpu::ComputePipeline& extend = camera ? *extendCamera_ : *extend_;
        const gpu::ComputePipeline& shade = camera ? *shadeCamera_ : *shade_;
        // The tail first: its few, long invocations then start at once and run while the shadow
        // pass fills the rest of the GPU, instead of waiting behind all of its workgroups.
        if (b <= maxBounces && tailPaths_ != 0)
            timed(cmd, kTail, b, [&] { tail_->dispatchIndirect(cmd, control_, tailArgs, &push); });
        if (b <= maxBounces) timed(cmd, kExtend, b, [&] { extend.dispatchIndirect(cmd, control_, extendArgs, &push); });
        if (b >= 1) timed(cmd, kShadow, b, [&] { shadow_->dispatchIndirect(cmd, control_, shadowArgs, &push); });
        gpu::computeBarrier(cmd);
        if (b <= maxBounces) {
            timed(cmd, kShade, b, [&] { shade.dispatchIndirect(cmd, control_, extendArgs, &push); });
            gpu::computeBarrier(cmd);
        }
    }
    timed(cmd, kFinish, maxBounces + 1, [&] { finish_->dispatch(cmd, groupsFor(std::uint64_t(tileWidth) * tileHeight), 1, 1, &push); });
}

std::vector<gpu::PipelineStatistic> WavefrontPass::statistics() const {
    std::vector<gpu::PipelineStatistic> out;
    for (const gpu::ComputePipeline* p : {extend_.get(), shade_.get(), shadow_.get()})
        for (gpu::PipelineStatistic& s : p->namedStatistics()) out.push_back(std::move(s));
    return out;
}

}  // namespace penumbra
