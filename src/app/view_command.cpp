// penumbra view [SCENE]: the interactive viewer (src/app/viewer/).
#include <memory>
#include <optional>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/viewer/viewer_app.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "image/write.h"

namespace penumbra::app {
namespace {

struct ViewArgs {
    std::string scene = "cornell";
    std::string map;
    CameraOverrides camera;
    viewer::ViewerOptions options;
    bool noVsync = false;
    std::string debug = "none";
    EnvironmentSpec env;
    WadOptions wad;
    std::string script;
    std::optional<double> fixedDt;
};

void runView(ViewArgs args) {
    if (args.options.width < 64 || args.options.height < 64 || args.options.width > 16384 || args.options.height > 16384)
        throw UsageError("--width and --height must be between 64 and 16384");
    if (args.options.samplesPerFrame < 1 || args.options.samplesPerFrame > 64)
        throw UsageError("--spp must be between 1 and 64 samples per frame");
    if (args.options.frames && *args.options.frames == 0) throw UsageError("--frames must be at least 1");
    if (!args.options.screenshot.empty()) {
        if (!args.options.frames) throw UsageError("--screenshot needs --frames N (the frame to capture)");
        if (formatFromPath(args.options.screenshot) != ImageFormat::Png) throw UsageError("--screenshot must be a .png file");
        checkWritable(args.options.screenshot);
    }
    if (args.fixedDt && !(*args.fixedDt > 0 && *args.fixedDt <= 1))
        throw UsageError("--fixed-dt must be a time step in seconds, above 0 and at most 1");
    args.options.fixedDt = args.fixedDt;
    if (args.options.stepsPerFrame < 1 || args.options.stepsPerFrame > 1000)
        throw UsageError("--steps-per-frame must be between 1 and 1000");
    if (args.options.stepsPerFrame > 1 && !args.fixedDt) throw UsageError("--steps-per-frame needs --fixed-dt");
    // Read before any window opens, so a bad script is one line and exit code 1.
    if (!args.script.empty()) args.options.script = viewer::loadInputScript(args.script);
    checkViewSettingRanges(args.options.view);
    args.options.vsync = !args.noVsync;
    args.options.debug = viewer::parseDebugView(args.debug);
    Scene scene = loadScene(args.scene, args.map, args.camera, nullptr, args.env, args.wad);
    viewer::runViewer(std::move(scene), args.options);
}

}  // namespace

void registerView(CLI::App& app, Action& action) {
    auto args = std::make_shared<ViewArgs>();
    CLI::App* cmd = app.add_subcommand("view", "open a window and explore a scene interactively (starts paused)");
    cmd->add_option("scene", args->scene, sceneArgumentHelp());
    cmd->add_option("--map", args->map, "level of a .wad file, e.g. E1M1 or MAP01 (default: the first)");
    cmd->add_option("--width", args->options.width, "window width (default 1280)");
    cmd->add_option("--height", args->options.height, "window height (default 720)");
    cmd->add_option("--spp", args->options.samplesPerFrame, "samples per pixel per frame (default 1)");
    cmd->add_flag("--no-vsync", args->noVsync, "present as fast as possible");
    cmd->add_option("--frames", args->options.frames, "automation: play at once, render N frames, then exit");
    cmd->add_option("--screenshot", args->options.screenshot, "automation: with --frames, write frame N to this PNG");
    cmd->add_option("--script", args->script,
                    "automation: play timed key and mouse events from this file (see docs/VIEWER.md); starts playing");
    cmd->add_option("--fixed-dt", args->fixedDt, "each frame advances time by this many seconds (reproducible runs)");
    cmd->add_option("--steps-per-frame", args->options.stepsPerFrame,
                    "automation: each drawn frame plays N steps of --fixed-dt (the same play in fewer frames)");
    cmd->add_flag("--print-camera", args->options.printCamera,
                  "on exit, print 'camera X,Y,Z direction DX,DY,DZ' (scene units)");
    cmd->add_flag("--fly", args->options.fly, "start in free flight on Doom levels (F toggles walking)");
    addPhantomOption(*cmd, args->options.phantom);
    cmd->add_flag("--denoise", args->options.denoise, "start with the a-trous denoiser on");
    addViewSettingOptions(*cmd, args->options.view);
    cmd->add_flag("--preview", args->options.preview,
                  "while the view moves, draw a fast preview (albedo times a cosine at the primary hits); path "
                  "tracing resumes at rest (V toggles it)");
    cmd->add_flag("--cull-backfaces", args->options.cullBackfaces,
                  "camera and bounce rays skip triangles seen from behind (not shadow rays, not glass)");
    cmd->add_flag_callback("--no-jitter", [args] { args->options.antiAliasing = false; },
                  "start with anti-aliasing off: camera rays through pixel centres (the panel toggles it)");
    cmd->add_option("--debug", args->debug, "start in a debug view: normals, albedo, depth, motion, samples, nodes, triangles, boxes, leaf-depth, leaf-triangles");
    addDeviceOption(*cmd, args->options.device);
    addBvhBuildOption(*cmd, args->options.bvhBuild);
    addBvhCacheOption(*cmd);
    addCameraOptions(*cmd, args->camera);
    addEnvironmentOptions(*cmd, args->env);
    addWadOptions(*cmd, args->wad);
    cmd->callback([args, &action] { action = [args] { runView(*args); }; });
}

}  // namespace penumbra::app
