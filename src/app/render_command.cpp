// penumbra render [SCENE]: progressive headless rendering to PNG or EXR.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "app/common_options.h"
#include "core/atomic_file.h"
#include "core/progress.h"
#include "image/write.h"
#include "render/renderer.h"

namespace penumbra::app {
namespace {

struct RenderArgs {
    std::string scene = "cornell";
    std::string map;
    std::string output;  // default: out/<scene>.png
    std::string device;
    std::string accel = "bvh";
    std::string mis = "both";
    float exposure = 0;
    bool quiet = false;
    CameraOverrides camera;
    EnvironmentSpec env;
    WadOptions wad;
    RenderSettings settings;
};

void runRender(const RenderArgs& args, const CLI::App& cmd) {
    RenderSettings settings = args.settings;
    settings.accel = parseAccel(args.accel);
    settings.mis = parseMisMode(args.mis);
    validateSettings(settings);
    SceneFileSettings fileSettings;
    Scene scene = loadScene(args.scene, args.map, args.camera, &fileSettings, args.env, args.wad);
    // A scene file's render settings apply unless the command line gave the same flag.
    auto fromFile = [&](const char* flag, const auto& value, auto& target) {
        if (value && cmd.count(flag) == 0) target = *value;
    };
    fromFile("--spp", fileSettings.samplesPerPixel, settings.samplesPerPixel);
    fromFile("--bounces", fileSettings.maxBounces, settings.maxBounces);
    fromFile("--width", fileSettings.width, settings.width);
    fromFile("--height", fileSettings.height, settings.height);
    float exposure = args.exposure;
    fromFile("--exposure", fileSettings.exposure, exposure);
    validateSettings(settings);

    std::filesystem::path output = args.output;
    if (output.empty()) {
        std::string stem = std::filesystem::path(args.scene).stem().string();
        if (!args.map.empty()) stem += "-" + args.map;
        output = std::filesystem::path("out") / (stem + ".png");
        std::error_code ec;
        std::filesystem::create_directories(output.parent_path(), ec);  // our own default folder
    }
    // Fail before rendering, not after: a bad name or folder would waste the whole render.
    formatFromPath(output);
    checkWritable(output);

    auto ctx = openDevice(args.device);
    Renderer renderer(*ctx, scene, settings);
    const bool showProgress = !args.quiet && isatty(STDERR_FILENO);
    ProgressBar progress("render", settings.samplesPerPixel, showProgress);
    auto start = std::chrono::steady_clock::now();
    renderer.render([&](std::uint32_t done) { progress.update(done); });
    progress.finish();
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    writeImage(output, renderer.image(), ToneMapSettings{exposure});
    const RenderStats& st = renderer.stats();
    const double rays = double(st.closestRays + st.shadowRays);
    const double gpuSeconds = st.gpuMilliseconds * 1e-3;
    if (st.invalidSamples)
        std::fprintf(stderr, "penumbra: warning: %llu path samples were NaN or infinite and were dropped\n",
                     static_cast<unsigned long long>(st.invalidSamples));
    if (!args.quiet)
        std::fprintf(stderr, "penumbra: %s %ux%u, %u spp, %s, in %.2f s (GPU %.2f s), %.1f Mrays/s -> %s\n",
                     scene.name.c_str(), settings.width, settings.height, st.samplesPerPixel,
                     ctx->info().name.c_str(), seconds, gpuSeconds,
                     gpuSeconds > 0 ? rays / gpuSeconds * 1e-6 : 0.0, output.string().c_str());
}

}  // namespace

void registerRender(CLI::App& app, Action& action) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "render a scene to a PNG (tone mapped) or EXR (linear HDR) file");
    cmd->add_option("scene", args->scene, sceneArgumentHelp());
    cmd->add_option("--map", args->map, "level of a .wad file, e.g. E1M1 or MAP01 (default: the first)");
    cmd->add_option("-o,--output", args->output, "output file, .png or .exr (default out/SCENE.png)");
    cmd->add_option("--spp", args->settings.samplesPerPixel, "samples per pixel");
    cmd->add_option("--bounces", args->settings.maxBounces, "maximum path segments after the camera ray");
    cmd->add_option("--width", args->settings.width, "image width in pixels");
    cmd->add_option("--height", args->settings.height, "image height in pixels");
    cmd->add_option("--seed", args->settings.seed, "random seed (same seed, same device: same image)");
    cmd->add_option("--accel", args->accel, "bvh, or brute (every triangle per ray: the oracle)");
    cmd->add_option("--mis", args->mis,
                    "direct light estimators: both (MIS, default), light (light sampling only) or bsdf (BSDF sampling only)");
    cmd->add_option("--exposure", args->exposure, "exposure in stops for PNG output");
    cmd->add_option("--time", args->settings.time, "seconds: the moment animated textures show (Doom's liquids; default 0)");
    cmd->add_flag("-q,--quiet", args->quiet, "no progress bar or summary");
    addDeviceOption(*cmd, args->device);
    addBvhCacheOption(*cmd);
    addCameraOptions(*cmd, args->camera);
    addEnvironmentOptions(*cmd, args->env);
    addWadOptions(*cmd, args->wad);
    cmd->callback([args, cmd, &action] { action = [args, cmd] { runRender(*args, *cmd); }; });
}

}  // namespace penumbra::app
