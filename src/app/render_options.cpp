#include "app/render_options.h"

#include <cstdlib>

#include "core/error.h"
#include "render/walks.h"

namespace penumbra::app {

AovSet parseAovs(const std::vector<std::string>& names) {
    AovSet set;
    for (const std::string& name : names) {
        if (name == "albedo") set.albedo = true;
        else if (name == "normal") set.normal = true;
        else if (name == "depth") set.depth = true;
        else if (name == "variance") set.variance = true;
        else if (name == "samples") set.samples = true;
        else throw UsageError("unknown --aov '" + name + "'; use albedo, normal, depth, variance or samples");
    }
    return set;
}

FrameRange parseFrames(const std::string& text) {
    const auto bad = [&]() {
        return UsageError("--frames expects a range of frame numbers like 1..48 (got '" + text + "')");
    };
    const std::size_t dots = text.find("..");
    if (dots == std::string::npos || dots == 0) throw bad();
    auto number = [&](const std::string& part) {
        char* end = nullptr;
        if (part.empty() || part.size() > 9 || !std::isdigit(static_cast<unsigned char>(part[0]))) throw bad();
        const long long v = std::strtoll(part.c_str(), &end, 10);
        if (*end != '\0') throw bad();
        return std::int64_t(v);
    };
    FrameRange r{number(text.substr(0, dots)), number(text.substr(dots + 2))};
    if (r.last < r.first) throw UsageError("--frames " + text + ": the last frame comes before the first");
    if (r.last - r.first >= 1000000) throw UsageError("--frames " + text + ": at most a million frames at once");
    return r;
}

std::filesystem::path statePathFor(const std::filesystem::path& output) {
    std::filesystem::path state = output;
    state += ".state";
    return state;
}

void addRenderOptions(CLI::App& cmd, RenderArgs& a) {
    cmd.add_option("scene", a.scene, sceneArgumentHelp());
    cmd.add_option("--map", a.map, "level of a .wad file, e.g. E1M1 or MAP01 (default: the first)");
    cmd.add_option("-o,--output", a.output,
                   "output file, .png or .exr (default out/SCENE.png), or a video (.mp4, .mkv, .mov) of --walk or --frames; "
                   "an image sequence's name takes the frame number as %04d");
    cmd.add_option("--spp", a.settings.samplesPerPixel, "samples per pixel (with --time-limit or --noise-threshold: at most)");
    cmd.add_option("--bounces", a.settings.maxBounces, "maximum path segments after the camera ray");
    cmd.add_option("--width", a.settings.width, "image width in pixels");
    cmd.add_option("--height", a.settings.height, "image height in pixels");
    cmd.add_option("--seed", a.settings.seed, "random seed (same seed, same device: same image)");
    cmd.add_option("--accel", a.accel, accelHelp());
    addBvhBuildOption(cmd, a.settings.bvhBuild);
    cmd.add_option("--mis", a.mis,
                   "direct light estimators: both (MIS, default), light (light sampling only) or bsdf (BSDF sampling only)");
    cmd.add_option("--shadow-roulette", a.settings.shadowRouletteShare,
                   "shadow rays carrying less than this share of their pixel's value so far go through Russian "
                   "roulette (same mean, fewer rays; default 0: every ray, which keeps an image the same bit for bit "
                   "however its passes are split across MPI ranks or checkpoints)");
    cmd.add_flag_callback("--no-jitter", [&a] { a.settings.pixelJitter = false; },
                 "camera rays through pixel centres: no anti-aliasing (jaggy edges, as the simplest ray tracers draw)");
    cmd.add_flag("--cull-backfaces", a.settings.cullBackfaces,
                 "camera and bounce rays skip triangles seen from behind (not shadow rays, not glass; for closed, "
                 "consistently wound meshes)");
    cmd.add_option("--exposure", a.exposure, "exposure in stops for PNG output");
    cmd.add_flag("-q,--quiet", a.quiet, "no progress bar or summary");
    cmd.add_option("--time-limit", a.timeLimit,
                   "wall-clock budget, e.g. 90, 90s, 2m or 1h30m: stop after the pass that reaches it (and --spp)");
    cmd.add_option("--noise-threshold", a.noiseThreshold,
                   "adaptive sampling: pixels whose relative error falls below X (e.g. 0.02) stop taking samples");
    cmd.add_option("--checkpoint", a.checkpointSeconds,
                   "every SECONDS, write the image so far and a state file (OUTPUT.state) that --resume continues");
    cmd.add_option("--resume", a.resume,
                   "continue the render a state file (OUTPUT.state) holds; with --frames, give the output pattern: "
                   "finished frames are skipped, interrupted ones continued");
    cmd.add_flag("--denoise", a.denoise, "denoise the image (edge-aware a-trous filter guided by albedo, normal and depth)");
    cmd.add_option("--aov", a.aovs, "extra layers in an EXR: albedo,normal,depth,variance,samples (docs/RENDERING.md)")
        ->delimiter(',');
    cmd.add_option("--frames", a.frames, "render frames A..B of an animated scene, each at time frame / --fps + --time");
    cmd.add_option("--time", a.time, "the moment of the scene to render, in seconds (camera paths, animations, Doom's animated textures)");
    cmd.add_option("--fps", a.fps, "frames per second of --frames (default 24)");
    cmd.add_option("--walk", a.walk,
                   "replay this walk (the viewer's --script events, at 1/--fps seconds a frame) and render its "
                   "camera path, frame by frame, to a video (-o walk.mp4, the default) or images (-o f_%04d.png)");
    cmd.add_flag("--viewer-quality", a.viewerQuality,
                 "walks and videos: render each frame as the viewer does (--spp samples a frame, default 1, "
                 "accumulated over frames; --denoise its denoiser) instead of a final frame");
    cmd.add_option("--progress", a.progress, "bar (default, on a terminal), json (lines on stdout) or none");
    cmd.add_flag("--mpi", a.mpi,
                 "render across the ranks of an MPI job (implied when started by mpirun; docs/DISTRIBUTED.md)");
    addDeviceOption(cmd, a.device);
    addWadOptions(cmd, a.wad);
    addPhantomOption(cmd, a.phantom);
    addBvhCacheOption(cmd);
    addCameraOptions(cmd, a.camera);
    addEnvironmentOptions(cmd, a.env);
}

}  // namespace penumbra::app
