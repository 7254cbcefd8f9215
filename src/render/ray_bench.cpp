#include "render/ray_bench.h"

#include <algorithm>

#include "core/error.h"
#include "core/median.h"
#include "gpu/commands.h"
#include "gpu/timer.h"
#include "render/kernel_features.h"
#include "render/scene_pipeline.h"

namespace penumbra {

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
    auto pipeline = makeScenePipeline(ctx, "raybench", renderer.gpuScene(), renderer.frameUniforms(),
                                      {PN_BINDING_SCRATCH, PN_BINDING_SCRATCH2},
                                      kernelFeatures(renderer.sceneArrays(), renderer.settings().accel));
    pipeline->bind(PN_BINDING_SCRATCH, points);
    pipeline->bind(PN_BINDING_SCRATCH2, results);

    auto timeMode = [&](std::uint32_t mode, std::uint32_t pass) {
        timer.reset();
        commands.run([&](VkCommandBuffer cmd) {
            shader::PassPush push{pass, mode, 0, 0};
            timer.begin(cmd, 0);
            pipeline->dispatch(cmd, (s.width + PN_TRACE_GROUP_X - 1) / PN_TRACE_GROUP_X,
                               (s.height + PN_TRACE_GROUP_Y - 1) / PN_TRACE_GROUP_Y, 1, &push);
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

    // One more frame, counted, for the frame's ray total (counting adds atomics, so untimed).
    const RenderStats before = renderer.stats();
    renderer.renderPasses(1, true);
    r.frameRays = (renderer.stats().closestRays - before.closestRays) + (renderer.stats().shadowRays - before.shadowRays);
    return r;
}

}  // namespace penumbra
