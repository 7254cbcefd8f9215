#include "render/ray_bench.h"

#include <algorithm>

#include "core/error.h"
#include "core/median.h"
#include "gpu/commands.h"
#include "gpu/timer.h"
#include "render/kernel_features.h"
#include "render/scene_pipeline.h"

namespace penumbra {

namespace {
constexpr std::uint32_t kWarpLanes = 32;
static_assert(kWarpLanes % PN_TRACE_GROUP_X == 0 && (PN_TRACE_GROUP_X * PN_TRACE_GROUP_Y) % kWarpLanes == 0,
              "a warp is whole rows of a trace group");
constexpr std::uint32_t kWarpRows = kWarpLanes / PN_TRACE_GROUP_X;
}  // namespace

TraversalWork traversalWork(std::span<const std::uint32_t> words, std::uint32_t width, std::uint32_t height) {
    PN_CHECK(words.size() == std::size_t(width) * height);
    TraversalWork w;
    std::uint64_t nodes = 0, primitives = 0, laneSteps = 0;
    for (std::uint32_t y0 = 0; y0 < height; y0 += kWarpRows)
        for (std::uint32_t x0 = 0; x0 < width; x0 += PN_TRACE_GROUP_X) {
            std::uint32_t longest = 0;
            for (std::uint32_t y = y0; y < std::min(y0 + kWarpRows, height); ++y)
                for (std::uint32_t x = x0; x < std::min(x0 + PN_TRACE_GROUP_X, width); ++x) {
                    const std::uint32_t word = words[std::size_t(y) * width + x];
                    if (word == 0) continue;
                    const std::uint32_t n = word & PN_RAY_WORK_MAX;
                    ++w.rays;
                    nodes += n;
                    primitives += word >> PN_RAY_WORK_BITS;
                    longest = std::max(longest, n);
                }
            laneSteps += std::uint64_t(longest) * kWarpLanes;
        }
    if (w.rays == 0) return w;
    w.nodesPerRay = double(nodes) / double(w.rays);
    w.primitivesPerRay = double(primitives) / double(w.rays);
    w.laneUse = laneSteps > 0 ? double(nodes) / double(laneSteps) : 0.0;
    return w;
}

RayBenchResult runRayBench(const gpu::Context& ctx, Renderer& renderer, int repeats) {
    if (!ctx.timestampsSupported())
        throw Error("device '" + ctx.info().name + "' has no GPU timestamps, so it cannot be benchmarked");
    PN_CHECK(repeats > 0);
    const RenderSettings& s = renderer.settings();
    const std::size_t pixels = std::size_t(s.width) * s.height;
    gpu::Commands commands(ctx);
    gpu::GpuTimer timer(ctx, 1);
    gpu::Buffer points(ctx, pixels * sizeof(shader::SurfacePoint), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                       gpu::MemoryKind::DeviceLocal);
    gpu::Buffer results(ctx, pixels * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                        gpu::MemoryKind::DeviceLocal);
    // The timed kernel and its counting twin, over the same points and results.
    // The renderer's kernels without counting: the ray rate is the walk's own.
    const KernelSpec spec = renderer.kernelSpec().withOption(PN_OPTION_FRAME_STATS, false);
    auto makeBench = [&](const char* shader) {
        auto made = makeScenePipeline(ctx, shader, renderer.gpuScene(), renderer.frameUniforms(),
                                      {PN_BINDING_SCRATCH, PN_BINDING_SCRATCH2}, spec);
        made->bind(PN_BINDING_SCRATCH, points);
        made->bind(PN_BINDING_SCRATCH2, results);
        return made;
    };
    auto pipeline = makeBench("raybench");
    auto counting = makeBench("raybench_count");
    // One ray of kind `mode` per pixel.
    auto dispatchRays = [&](const gpu::ComputePipeline& p, VkCommandBuffer cmd, std::uint32_t mode, std::uint32_t pass) {
        shader::PassPush push{pass, mode, 0, 0};
        p.dispatch(cmd, (s.width + PN_TRACE_GROUP_X - 1) / PN_TRACE_GROUP_X, (s.height + PN_TRACE_GROUP_Y - 1) / PN_TRACE_GROUP_Y,
                   1, &push);
    };

    auto timeMode = [&](std::uint32_t mode, std::uint32_t pass) {
        timer.reset();
        commands.run([&](VkCommandBuffer cmd) {
            timer.begin(cmd, 0);
            dispatchRays(*pipeline, cmd, mode, pass);
            timer.end(cmd, 0);
        });
        return timer.milliseconds(0);
    };

    RayBenchResult r;
    r.repeats = repeats;
    // Warm-up: pipeline creation and first-touch costs stay out of the figures.
    timeMode(PN_RAYBENCH_PRIMARY, 0);
    renderer.renderPasses(1, false);

    std::vector<double> primary, shadow, diffuse, frame;
    for (int i = 0; i < repeats; ++i) {
        primary.push_back(timeMode(PN_RAYBENCH_PRIMARY, 0));  // same points every time
        shadow.push_back(timeMode(PN_RAYBENCH_SHADOW, std::uint32_t(i)));
        diffuse.push_back(timeMode(PN_RAYBENCH_DIFFUSE, std::uint32_t(i)));
        frame.push_back(renderer.renderPasses(1, false));
    }
    auto kept = gpu::downloadBuffer<shader::SurfacePoint>(ctx, commands, points, pixels);
    std::uint64_t valid = std::count_if(kept.begin(), kept.end(), [](const shader::SurfacePoint& p) { return p.valid != 0; });
    r.primaryRays = pixels;
    // The shadow rays the last shadow pass traced (it writes -1 where no light reached a point).
    timeMode(PN_RAYBENCH_SHADOW, 0);
    auto shadowResults = gpu::downloadBuffer<float>(ctx, commands, results, pixels);
    r.shadowRays = std::uint64_t(std::count_if(shadowResults.begin(), shadowResults.end(), [](float v) { return v >= 0; }));
    r.diffuseRays = valid;
    r.primaryMs = median(primary);
    r.shadowMs = median(shadow);
    r.diffuseMs = median(diffuse);
    r.frameMs = median(frame);

    // The walk's work for the rays of pass 0, untimed (primary first: it writes the points).
    auto countMode = [&](std::uint32_t mode) {
        commands.run([&](VkCommandBuffer cmd) { dispatchRays(*counting, cmd, mode, 0); });
        const auto words = gpu::downloadBuffer<std::uint32_t>(ctx, commands, results, pixels);
        return traversalWork(words, s.width, s.height);
    };
    r.primaryWork = countMode(PN_RAYBENCH_PRIMARY);
    r.shadowWork = countMode(PN_RAYBENCH_SHADOW);
    r.diffuseWork = countMode(PN_RAYBENCH_DIFFUSE);

    // One more frame, counted, for the frame's ray total (counting adds atomics, so untimed).
    const RenderStats before = renderer.stats();
    renderer.renderPasses(1, true);
    r.frameRays = (renderer.stats().closestRays - before.closestRays) + (renderer.stats().shadowRays - before.shadowRays);

    // And one with the kernels that count tests, hits and blocked shadow rays (slower, untimed).
    renderer.setFrameStatistics(true);
    const RenderStats counted = renderer.stats();
    renderer.renderPasses(1, true);
    const RenderStats& after = renderer.stats();
    r.frameStats = {after.closestRays - counted.closestRays, after.closestHits - counted.closestHits,
                    after.shadowRays - counted.shadowRays, after.shadowBlocked - counted.shadowBlocked,
                    after.primitivesTested - counted.primitivesTested};
    renderer.setFrameStatistics(false);
    return r;
}

}  // namespace penumbra
