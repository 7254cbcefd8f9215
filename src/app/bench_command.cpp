// penumbra bench [SCENE]: BVH build time, rays per second by kind, and one frame's GPU time.
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "app/common_options.h"
#include "render/ray_bench.h"

namespace penumbra::app {
namespace {

struct BenchArgs {
    std::string scene = "cornell";
    std::string map;
    std::string device;
    std::string accel = "bvh";
    std::uint32_t width = 1920, height = 1080, bounces = 4;
    int repeats = 20;
    bool json = false;
    EnvironmentSpec env;
};

double mrays(std::uint64_t rays, double ms) { return ms > 0 ? double(rays) / (ms * 1e3) : 0.0; }

void runBench(const BenchArgs& args) {
    if (args.repeats < 1 || args.repeats > 10000) throw UsageError("--repeats must be between 1 and 10000");
    RenderSettings settings;
    settings.width = args.width;
    settings.height = args.height;
    settings.maxBounces = args.bounces;
    settings.samplesPerPixel = 1;
    settings.accel = parseAccel(args.accel);
    validateSettings(settings);
    Scene scene = loadScene(args.scene, args.map, {}, nullptr, args.env);
    auto ctx = openDevice(args.device);
    Renderer renderer(*ctx, scene, settings);
    RayBenchResult r = runRayBench(*ctx, renderer, args.repeats);
    const SceneArrays& a = renderer.sceneArrays();

    if (args.json) {
        std::printf(
            "{\n  \"scene\": \"%s\",\n  \"device\": \"%s\",\n  \"accel\": \"%s\",\n  \"width\": %u,\n  \"height\": %u,\n"
            "  \"bounces\": %u,\n  \"repeats\": %d,\n  \"triangles\": %zu,\n  \"bvh_nodes\": %zu,\n  \"bvh_sah_cost\": %.3f,\n"
            "  \"bvh_build_ms\": %.3f,\n  \"bvh_from_cache\": %s,\n  \"primary_mrays_per_s\": %.1f,\n  \"shadow_mrays_per_s\": %.1f,\n"
            "  \"diffuse_mrays_per_s\": %.1f,\n  \"primary_ms\": %.4f,\n  \"shadow_ms\": %.4f,\n  \"diffuse_ms\": %.4f,\n"
            "  \"frame_ms\": %.4f,\n  \"frame_rays\": %llu,\n  \"frame_mrays_per_s\": %.1f\n}\n",
            scene.name.c_str(), ctx->info().name.c_str(), accelName(settings.accel), settings.width, settings.height,
            settings.maxBounces, r.repeats, a.triVerts.size(), a.nodes.size(), a.stats.sahCost, a.buildMilliseconds,
            a.bvhFromCache ? "true" : "false", mrays(r.primaryRays, r.primaryMs), mrays(r.shadowRays, r.shadowMs), mrays(r.diffuseRays, r.diffuseMs),
            r.primaryMs, r.shadowMs, r.diffuseMs, r.frameMs, static_cast<unsigned long long>(r.frameRays),
            mrays(r.frameRays, r.frameMs));
        return;
    }
    std::printf("%s on %s, %ux%u, accel %s, medians of %d runs\n", scene.name.c_str(), ctx->info().name.c_str(),
                settings.width, settings.height, accelName(settings.accel), r.repeats);
    std::printf("  bvh build        %10.3f ms  (%zu triangles, %zu nodes, SAH cost %.2f%s)\n", a.buildMilliseconds,
                a.triVerts.size(), a.nodes.size(), a.stats.sahCost, a.bvhFromCache ? ", read from the cache" : "");
    if (!a.env.alias.empty())
        std::printf("  env table build  %10.3f ms  (%ux%u texels)\n", a.envBuildMilliseconds, a.env.width, a.env.height);
    std::printf("  primary rays     %10.1f Mrays/s  (%.3f ms)\n", mrays(r.primaryRays, r.primaryMs), r.primaryMs);
    std::printf("  shadow rays      %10.1f Mrays/s  (%.3f ms)\n", mrays(r.shadowRays, r.shadowMs), r.shadowMs);
    std::printf("  diffuse bounces  %10.1f Mrays/s  (%.3f ms)\n", mrays(r.diffuseRays, r.diffuseMs), r.diffuseMs);
    std::printf("  frame, 1 spp, %u bounces + NEE: %.3f ms (%.1f Mrays/s)\n", settings.maxBounces, r.frameMs,
                mrays(r.frameRays, r.frameMs));
}

}  // namespace

void registerBench(CLI::App& app, Action& action) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* cmd = app.add_subcommand("bench", "measure BVH build, rays per second and frame time on the GPU");
    cmd->add_option("scene", args->scene, "built-in scene or scene file");
    cmd->add_option("--map", args->map, "level of a .wad file");
    cmd->add_option("--width", args->width, "frame width (default 1920)");
    cmd->add_option("--height", args->height, "frame height (default 1080)");
    cmd->add_option("--bounces", args->bounces, "bounces of the timed frame (default 4)");
    cmd->add_option("--repeats", args->repeats, "timed runs per figure; medians are reported (default 20)");
    cmd->add_option("--accel", args->accel, "bvh or brute");
    cmd->add_flag("--json", args->json, "print one JSON object instead of text");
    addDeviceOption(*cmd, args->device);
    addBvhCacheOption(*cmd);
    addEnvironmentOptions(*cmd, args->env);
    cmd->callback([args, &action] { action = [args] { runBench(*args); }; });
}

}  // namespace penumbra::app
