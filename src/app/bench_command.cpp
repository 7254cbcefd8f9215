// penumbra bench [SCENE]: BVH build time, rays per second by kind, and one frame's GPU time.
#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "app/common_options.h"
#include "image/write.h"
#include "render/bvh_build_compare.h"
#include "render/gpu_scene.h"
#include "render/ray_bench.h"
#include "render/viewer_bench.h"
#include "render/walks.h"

namespace penumbra::app {
namespace {

struct BenchArgs {
    std::string scene = "cornell";
    std::string map;
    std::string device;
    std::string accel = "bvh";
    BvhBuild bvhBuild = BvhBuild::Cpu;
    bool cullBackfaces = false;
    std::uint32_t width = 1920, height = 1080, bounces = 4;
    int repeats = 20;
    bool json = false;
    EnvironmentSpec env;
    WadOptions wad;
    CameraOverrides camera;
    // --viewer: the viewer's whole frame
    bool viewer = false;
    std::uint32_t spp = 1, denoise = 5;
    std::optional<std::uint32_t> rouletteStart;  // unset: the scene's, as in the viewer
    bool noTemporal = false;
    bool moveSectors = false;
    bool shareCameraRays = false;
    float shadowRoulette = kDefaultShadowRouletteShare;
    std::string motion = "static";
    int frames = 200;
    int warmupFrames = 30;
    double warmupSeconds = 1.5;
    std::string reference;
    double budgetMs = 100;
    int errorTrials = 1;
    int budgetFrames = 0;
    std::string errorMotion = "static";
    bool denoiseFilterOnly = false;
};

double mrays(std::uint64_t rays, double ms) { return ms > 0 ? double(rays) / (ms * 1e3) : 0.0; }

std::array<std::pair<const char*, const TraversalWork*>, 3> rayWork(const RayBenchResult& r) {
    return {{{"primary", &r.primaryWork}, {"shadow", &r.shadowWork}, {"diffuse", &r.diffuseWork}}};
}

// A JSON string's contents: quotes, backslashes and control characters escaped.
std::string jsonEscape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
        out += c;
    }
    return out;
}

// ,"key": { "executable: statistic": "value", ... } (the driver's words for each pipeline).
void printStatisticsJson(const char* key, const std::vector<gpu::PipelineStatistic>& statistics) {
    std::printf(",\n  \"%s\": {", key);
    const char* sep = "";
    for (const gpu::PipelineStatistic& s : statistics) {
        std::printf("%s\n    \"%s\": \"%s\"", sep, jsonEscape(s.executable + ": " + s.name).c_str(), jsonEscape(s.value).c_str());
        sep = ",";
    }
    std::printf("\n  }");
}

void printStatisticsText(const char* kind, const std::vector<gpu::PipelineStatistic>& statistics) {
    for (const gpu::PipelineStatistic& s : statistics)
        std::printf("  %s pipeline, %s: %s = %s\n", kind, s.executable.c_str(), s.name.c_str(), s.value.c_str());
}

void printViewerJson(const BenchArgs& args, const Scene& scene, const gpu::Context& ctx, const ViewerBenchOptions& o,
                     const ViewerBenchResult& r) {
    std::printf("{\n  \"scene\": \"%s\",\n  \"device\": \"%s\",\n  \"width\": %u,\n  \"height\": %u,\n"
                "  \"spp\": %u,\n  \"bounces\": %u,\n  \"roulette_start\": %u,\n  \"temporal\": %s,\n"
                "  \"denoise_passes\": %u,\n  \"denoise_filter_only\": %s,\n  \"shared_camera_rays\": %s,\n  \"shadow_roulette\": %.3g,\n  \"camera_motion\": \"%s\",\n  \"move_sectors\": %s,\n  \"frames\": %d,\n  \"viewer_frame_ms\": %.4f,\n  \"passes\": {",
                jsonEscape(scene.name).c_str(), jsonEscape(ctx.info().name).c_str(), o.width, o.height, o.view.samplesPerFrame,
                o.view.maxBounces, o.view.rouletteStart, o.view.temporal ? "true" : "false",
                o.view.denoise ? o.view.denoiseIterations : 0, o.view.denoiseConverges ? "false" : "true",
                o.view.shareCameraRays ? "true" : "false", o.view.shadowRouletteShare, cameraMotionName(o.motion),
                o.moveSectors ? "true" : "false", r.frames, r.frameMs);
    const char* sep = "";
    for (const auto& [name, ms] : r.passMs) {
        std::printf("%s\n    \"%s\": %.4f", sep, name.c_str(), ms);
        sep = ",";
    }
    std::printf("\n  },\n  \"rays_per_pixel_per_sample\": %.3f,\n  \"trace_mrays_per_s\": %.1f", r.raysPerPixelPerSample,
                r.mraysPerSecond);
    std::printf(",\n  \"kernel_features\": \"%s\"", r.kernelFeatures.c_str());
    printStatisticsJson("trace_pipeline", r.traceStatistics);
    printStatisticsJson("image_pipeline", r.imageStatistics);
    if (r.relMseRaw)
        std::printf(",\n  \"budget_ms\": %.2f,\n  \"budget_frames\": %d,\n  \"error_trials\": %d,\n  \"error_camera_motion\": \"%s\",\n  \"rel_mse_raw\": %.6g",
                    args.budgetMs, r.budgetFrames, o.errorTrials, cameraMotionName(o.errorMotion), *r.relMseRaw);
    if (r.relMseDenoised) std::printf(",\n  \"rel_mse_denoised\": %.6g", *r.relMseDenoised);
    std::printf("\n}\n");
}

void printViewerText(const Scene& scene, const gpu::Context& ctx, const ViewerBenchOptions& o,
                     const ViewerBenchResult& r) {
    std::printf("%s on %s, viewer frame %ux%u, %u spp, %u bounces (roulette from %u), temporal %s, %u denoise passes, camera %s; "
                "medians of %d frames\n",
                scene.name.c_str(), ctx.info().name.c_str(), o.width, o.height, o.view.samplesPerFrame,
                o.view.maxBounces, o.view.rouletteStart, o.view.temporal ? "on" : "off", o.view.denoise ? o.view.denoiseIterations : 0,
                cameraMotionName(o.motion), r.frames);
    std::printf("  whole frame      %10.3f ms\n", r.frameMs);
    for (const auto& [name, ms] : r.passMs) std::printf("  %-16s %10.3f ms\n", name.c_str(), ms);
    std::printf("  rays per pixel per sample %.2f, trace %.1f Mrays/s\n", r.raysPerPixelPerSample, r.mraysPerSecond);
    std::printf("  kernel specialised for: %s\n", r.kernelFeatures.c_str());
    printStatisticsText("trace", r.traceStatistics);
    printStatisticsText("image", r.imageStatistics);
    if (r.relMseRaw)
        std::printf("  error over %d frames (camera %s): relMSE raw %.5g", r.budgetFrames, cameraMotionName(o.errorMotion),
                    *r.relMseRaw);
    if (r.relMseDenoised) std::printf(", denoised %.5g", *r.relMseDenoised);
    if (r.relMseRaw) std::printf("\n");
}

void runViewerBenchCommand(const BenchArgs& args) {
    ViewerBenchOptions o;
    o.width = args.width;
    o.height = args.height;
    o.view.samplesPerFrame = args.spp;
    o.view.maxBounces = args.bounces;
    o.view.temporal = !args.noTemporal;
    o.moveSectors = args.moveSectors;
    o.view.shareCameraRays = args.shareCameraRays;
    o.cullBackfaces = args.cullBackfaces;
    o.bvhBuild = args.bvhBuild;
    o.view.denoise = args.denoise > 0;
    o.view.denoiseIterations = std::max(args.denoise, 1u);
    o.view.denoiseConverges = !args.denoiseFilterOnly;
    o.motion = parseCameraMotion(args.motion);
    o.frames = args.frames;
    o.warmupSeconds = args.warmupSeconds;
    o.warmupFrames = args.warmupFrames;
    if (args.warmupFrames < 0 || args.warmupFrames > 100000) throw UsageError("--warmup-frames must be within [0, 100000]");
    if (args.spp < 1 || args.spp > 64) throw UsageError("--spp must be between 1 and 64 for --viewer");
    if (args.denoise > 5) throw UsageError("--denoise must be between 0 (off) and 5 passes");
    validateShadowRouletteShare(args.shadowRoulette);
    o.view.shadowRouletteShare = args.shadowRoulette;
    if (!(args.warmupSeconds >= 0 && args.warmupSeconds <= 60)) throw UsageError("--warmup-seconds must be within [0, 60]");
    if (!args.reference.empty()) {
        if (!(args.budgetMs > 0 && args.budgetMs <= 1e6)) throw UsageError("--budget-ms must be within (0, 1e6]");
        o.reference = readExr(args.reference);
        o.budgetMs = args.budgetMs;
        if (args.errorTrials < 1 || args.errorTrials > 1000) throw UsageError("--error-trials must be between 1 and 1000");
        o.errorTrials = args.errorTrials;
        if (args.budgetFrames < 0 || args.budgetFrames > 1000000) throw UsageError("--budget-frames must be within [0, 1000000]");
        o.budgetFrameCount = args.budgetFrames;
        o.errorMotion = parseCameraMotion(args.errorMotion);
    }
    Scene scene = loadScene(args.scene, args.map, args.camera, nullptr, args.env, args.wad);
    const bool torch = scene.torch.enabled && scene.torch.intensity > 0;
    o.view.torch = torch;
    o.view.torchColor = scene.torch.color;
    o.view.torchIntensity = scene.torch.intensity;
    o.view.torchRange = scene.torch.range;
    o.view.rouletteStart = args.rouletteStart.value_or(
        scene.viewerRouletteStart.value_or(ViewSettings{}.rouletteStart));
    if (scene.camera.apertureRadius > 0) {
        o.view.apertureRadius = scene.camera.apertureRadius;
        o.view.focusDistance = scene.camera.focusDistance;
    }
    auto ctx = openDevice(args.device);
    const ViewerBenchResult r = runViewerBench(*ctx, scene, torch, o);
    if (args.json) printViewerJson(args, scene, *ctx, o, r);
    else printViewerText(scene, *ctx, o, r);
}

// --bvh-build and, for gpu, the GPU build's median time (timestamps) and SAH cost beside the CPU's:
// JSON members, each line ending in a comma.
void printGpuBuildJson(const gpu::Context& ctx, const Scene& scene, BvhBuild where, int repeats) {
    std::printf("  \"bvh_build\": \"%s\",\n", bvhBuildName(where));
    if (where != BvhBuild::Gpu) return;
    const BvhBuildComparison c = compareBvhBuilds(ctx, worldPrimitiveBounds(scene), repeats);
    std::printf("  \"gpu_bvh_build_ms\": %.4f,\n  \"gpu_bvh_build_repeats\": %d,\n  \"gpu_bvh_built_on_gpu\": %s,\n"
                "  \"gpu_bvh_sah_cost\": %.3f,\n  \"cpu_bvh_sah_cost\": %.3f,\n  \"gpu_bvh_sah_ratio\": %.4f,\n",
                c.gpuMilliseconds, c.repeats, c.onGpu ? "true" : "false", c.gpuSahCost, c.cpuSahCost,
                c.cpuSahCost > 0 ? c.gpuSahCost / c.cpuSahCost : 0.0);
}

void runBench(const BenchArgs& args) {
    if (args.viewer) return runViewerBenchCommand(args);
    if (args.repeats < 1 || args.repeats > 10000) throw UsageError("--repeats must be between 1 and 10000");
    RenderSettings settings;
    settings.width = args.width;
    settings.height = args.height;
    settings.maxBounces = args.bounces;
    settings.samplesPerPixel = 1;
    settings.accel = parseAccel(args.accel);
    settings.bvhBuild = args.bvhBuild;
    settings.cullBackfaces = args.cullBackfaces;
    validateSettings(settings);
    Scene scene = loadScene(args.scene, args.map, args.camera, nullptr, args.env, args.wad);
    auto ctx = openDevice(args.device);
    Renderer renderer(*ctx, scene, settings);
    RayBenchResult r = runRayBench(*ctx, renderer, args.repeats);
    const SceneArrays& a = renderer.sceneArrays();
    if (settings.accel == Accel::Wide && a.wideNodes.empty())
        std::fprintf(stderr, "penumbra: warning: this scene has instances, which the wide BVH does not cover: the figures are the binary BVH's\n");

    if (args.json) {
        std::printf(
            "{\n  \"scene\": \"%s\",\n  \"device\": \"%s\",\n  \"accel\": \"%s\",\n  \"cull_backfaces\": %s,\n  \"width\": %u,\n  \"height\": %u,\n"
            "  \"bounces\": %u,\n  \"repeats\": %d,\n  \"triangles\": %zu,\n  \"bvh_nodes\": %zu,\n  \"wide_nodes\": %zu,\n  \"bvh_sah_cost\": %.3f,\n"
            "  \"bvh_build_ms\": %.3f,\n  \"bvh_from_cache\": %s,\n  \"primary_mrays_per_s\": %.1f,\n  \"shadow_mrays_per_s\": %.1f,\n"
            "  \"diffuse_mrays_per_s\": %.1f,\n  \"primary_ms\": %.4f,\n  \"shadow_ms\": %.4f,\n  \"diffuse_ms\": %.4f,\n"
            "  \"frame_ms\": %.4f,\n  \"frame_rays\": %llu,\n  \"frame_mrays_per_s\": %.1f,\n",
            scene.name.c_str(), ctx->info().name.c_str(), accelName(settings.accel),
            settings.cullBackfaces ? "true" : "false", settings.width, settings.height, settings.maxBounces, r.repeats, a.triVerts.size(), a.nodes.size(), a.wideNodes.size(), a.stats.sahCost,
            a.buildMilliseconds, a.bvhFromCache ? "true" : "false", mrays(r.primaryRays, r.primaryMs), mrays(r.shadowRays, r.shadowMs), mrays(r.diffuseRays, r.diffuseMs),
            r.primaryMs, r.shadowMs, r.diffuseMs, r.frameMs, static_cast<unsigned long long>(r.frameRays),
            mrays(r.frameRays, r.frameMs));
        printGpuBuildJson(*ctx, scene, settings.bvhBuild, args.repeats);
        std::printf("  \"traversal\": {");
        const char* sep = "";
        for (const auto& [kind, w] : rayWork(r)) {
            std::printf("%s\n    \"%s\": {\"rays\": %llu, \"nodes_per_ray\": %.2f, \"primitives_per_ray\": %.2f, \"lane_use\": %.3f}",
                        sep, kind, static_cast<unsigned long long>(w->rays), w->nodesPerRay, w->primitivesPerRay, w->laneUse);
            sep = ",";
        }
        const auto& fs = r.frameStats;
        std::printf("\n  },\n  \"frame_statistics\": {\"closest_rays\": %llu, \"closest_hits\": %llu, \"shadow_rays\": %llu, "
                    "\"shadow_blocked\": %llu, \"primitives_tested\": %llu}\n}\n",
                    static_cast<unsigned long long>(fs.closestRays), static_cast<unsigned long long>(fs.closestHits),
                    static_cast<unsigned long long>(fs.shadowRays), static_cast<unsigned long long>(fs.shadowBlocked),
                    static_cast<unsigned long long>(fs.primitivesTested));
        return;
    }
    std::printf("%s on %s, %ux%u, accel %s%s, medians of %d runs\n", scene.name.c_str(), ctx->info().name.c_str(),
                settings.width, settings.height, accelName(settings.accel),
                settings.cullBackfaces ? " culling back faces" : "", r.repeats);
    std::printf("  bvh build        %10.3f ms  (%zu triangles, %zu nodes, SAH cost %.2f%s)\n", a.buildMilliseconds,
                a.triVerts.size(), a.nodes.size(), a.stats.sahCost,
                a.bvhFromCache ? ", read from the cache" : a.bvhBuiltOnGpu ? ", on the GPU, wall clock" : "");
    if (settings.bvhBuild == BvhBuild::Gpu) {
        const BvhBuildComparison c = compareBvhBuilds(*ctx, worldPrimitiveBounds(scene), args.repeats);
        std::printf("  gpu bvh build    %10.3f ms  (GPU timestamps, median of %d; SAH cost %.2f, the CPU build's %.2f)\n",
                    c.gpuMilliseconds, c.repeats, c.gpuSahCost, c.cpuSahCost);
    }
    if (!a.env.alias.empty())
        std::printf("  env table build  %10.3f ms  (%ux%u texels)\n", a.envBuildMilliseconds, a.env.width, a.env.height);
    std::printf("  primary rays     %10.1f Mrays/s  (%.3f ms)\n", mrays(r.primaryRays, r.primaryMs), r.primaryMs);
    std::printf("  shadow rays      %10.1f Mrays/s  (%.3f ms)\n", mrays(r.shadowRays, r.shadowMs), r.shadowMs);
    std::printf("  diffuse bounces  %10.1f Mrays/s  (%.3f ms)\n", mrays(r.diffuseRays, r.diffuseMs), r.diffuseMs);
    std::printf("  frame, 1 spp, %u bounces + NEE: %.3f ms (%.1f Mrays/s)\n", settings.maxBounces, r.frameMs,
                mrays(r.frameRays, r.frameMs));
    for (const auto& [kind, w] : rayWork(r))
        std::printf("  %-8s walk: %.1f nodes and %.1f primitives per ray, %.0f%% of warp lanes busy\n", kind, w->nodesPerRay,
                    w->primitivesPerRay, 100.0 * w->laneUse);
    const auto& fs = r.frameStats;
    std::printf("  frame statistics: %llu closest-hit rays (%llu hit), %llu shadow rays (%llu blocked), %llu primitives tested\n",
                static_cast<unsigned long long>(fs.closestRays), static_cast<unsigned long long>(fs.closestHits),
                static_cast<unsigned long long>(fs.shadowRays), static_cast<unsigned long long>(fs.shadowBlocked),
                static_cast<unsigned long long>(fs.primitivesTested));
}

}  // namespace

void registerBench(CLI::App& app, Action& action) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* cmd = app.add_subcommand("bench", "measure BVH build, rays per second and frame time on the GPU");
    cmd->add_option("scene", args->scene, sceneArgumentHelp());
    cmd->add_option("--map", args->map, "level of a .wad file");
    cmd->add_option("--width", args->width, "frame width (default 1920)");
    cmd->add_option("--height", args->height, "frame height (default 1080)");
    cmd->add_option("--bounces", args->bounces, "bounces of the timed frame (default 4)");
    cmd->add_option("--repeats", args->repeats, "timed runs per figure; medians are reported (default 20)");
    cmd->add_option("--accel", args->accel, accelHelp());
    addBvhBuildOption(*cmd, args->bvhBuild);
    cmd->add_flag("--cull-backfaces", args->cullBackfaces,
                  "closest-hit walks skip triangles seen from behind (not shadow rays, not glass)");
    cmd->add_flag("--json", args->json, "print one JSON object instead of text");
    cmd->add_flag("--viewer", args->viewer,
                  "time the viewer's whole frame (trace, G-buffer, temporal, denoise, tonemap) instead of ray kernels");
    cmd->add_option("--spp", args->spp, "--viewer: samples per pixel per frame (default 1)");
    cmd->add_option("--denoise", args->denoise, "--viewer: a-trous denoiser passes, 0 turns it off (default 5)");
    cmd->add_flag("--no-temporal", args->noTemporal, "--viewer: no temporal accumulation");
    cmd->add_flag("--move-sectors", args->moveSectors,
                  "--viewer, Doom levels: every door, lift, floor and crusher moves while timing (issue 40's target)");
    cmd->add_flag("--share-camera-rays", args->shareCameraRays,
                  "--viewer: a pixel's samples in a frame share one camera ray (the viewer's option; faster, raw mean noisier)");
    cmd->add_option("--shadow-roulette", args->shadowRoulette,
                    "--viewer: shadow rays carrying less than this share of their pixel's value so far go through "
                    "Russian roulette (0 traces all; default 0.1)");
    cmd->add_option("--roulette-start", args->rouletteStart, "--viewer: bounce from which Russian roulette may end paths (default as in the viewer: 2 for WAD levels, else 3)");
    cmd->add_option("--camera-motion", args->motion, "--viewer: static, orbit or walk (default static)");
    cmd->add_option("--frames", args->frames, "--viewer: timed frames (default 200)");
    cmd->add_option("--warmup-frames", args->warmupFrames, "--viewer: untimed frames first, at least (default 30)");
    cmd->add_option("--warmup-seconds", args->warmupSeconds, "--viewer: untimed warm-up time, at least (default 1.5)");
    cmd->add_option("--reference", args->reference,
                    "--viewer: a converged EXR of the same view and size; reports the error after --budget-ms of frames");
    cmd->add_option("--budget-ms", args->budgetMs, "--viewer: GPU time budget of the equal-time error (default 100)");
    cmd->add_option("--budget-frames", args->budgetFrames,
                    "--viewer: measure the error after exactly this many frames instead of --budget-ms (same images "
                    "for builds that differ only after the trace)");
    cmd->add_flag("--denoise-filter-only", args->denoiseFilterOnly,
                  "--viewer: the a-trous filter's output alone, not weighed against the running mean (which a still "
                  "view then never converges to; for comparisons)");
    cmd->add_option("--error-camera-motion", args->errorMotion,
                    "--viewer: the error's frames are still (default) or move (walk, orbit) to end on the reference's "
                    "view; needs --budget-frames");
    cmd->add_option("--error-trials", args->errorTrials,
                    "--viewer: repeat the equal-time error this many times, each from a fresh history with new random "
                    "numbers, and report the means (default 1)");
    addDeviceOption(*cmd, args->device);
    addBvhCacheOption(*cmd);
    addEnvironmentOptions(*cmd, args->env);
    addWadOptions(*cmd, args->wad);
    addCameraOptions(*cmd, args->camera);
    cmd->callback([args, &action] { action = [args] { runBench(*args); }; });
}

}  // namespace penumbra::app
