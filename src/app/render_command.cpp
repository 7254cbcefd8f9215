// penumbra render [SCENE]: final frames and image sequences to PNG or EXR (docs/RENDERING.md).
// The flags live in render_options.cpp, one frame's work in render_frame.cpp, sequences in
// render_sequence.cpp, the files in render_outputs.cpp.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "app/render_frame.h"
#include "app/render_outputs.h"
#include "app/render_options.h"
#include "app/render_ranks.h"
#include "app/render_sequence.h"
#include "core/atomic_file.h"
#include "core/duration.h"
#include "core/error.h"
#include "image/video_writer.h"
#include "image/write.h"
#include "interact/input_script.h"
#include "scene/animation.h"
#include "scene/phantom.h"

namespace penumbra::app {
namespace {

// What a CPU implementation (lavapipe) renders by default: about ten seconds of work.
constexpr std::uint32_t kCpuWidth = 320, kCpuHeight = 240;
constexpr double kCpuSeconds = 10;

struct LoadedRender {
    Scene scene;
    FrameJob job;
};

// The scene, and the settings with the scene file's defaults under the command line's flags.
LoadedRender loadRender(const RenderArgs& args, const CLI::App& cmd) {
    LoadedRender r;
    RenderSettings& settings = r.job.settings;
    settings = args.settings;
    settings.accel = parseAccel(args.accel);
    settings.mis = parseMisMode(args.mis);
    validateSettings(settings);
    SceneFileSettings fileSettings;
    r.scene = loadScene(args.scene, args.map, args.camera, &fileSettings, args.env, args.wad);
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
    r.job.toneMap = ToneMapSettings{exposure};
    validateSettings(settings);
    // Sizes and budgets the user chose (on the command line or in the scene file) are kept on a CPU.
    r.job.quiet = args.quiet;
    const bool sized = cmd.count("--width") || cmd.count("--height") || fileSettings.width || fileSettings.height;
    const bool budgeted = cmd.count("--spp") || cmd.count("--time-limit") || fileSettings.samplesPerPixel;
    r.job.progressLabel = sized || budgeted ? "render" : "";  // "": the CPU default may apply
    return r;
}

// The final-frame flags, checked (budget, adaptivity, checkpoints, outputs, progress).
void applyFrameOptions(const RenderArgs& args, FrameJob& job) {
    if (!args.timeLimit.empty()) job.timeLimit = parseDuration(args.timeLimit, "--time-limit");
    if (!(args.noiseThreshold >= 0 && args.noiseThreshold < 1))
        throw UsageError("--noise-threshold must be a relative error between 0 and 1, e.g. 0.02");
    job.adaptive.threshold = args.noiseThreshold;
    if (!(args.checkpointSeconds >= 0 && args.checkpointSeconds <= 1e7))
        throw UsageError("--checkpoint must be a number of seconds >= 0");
    job.checkpointSeconds = args.checkpointSeconds;
    job.denoise = args.denoise;
    job.aovs = parseAovs(args.aovs);
    if (args.progress == "bar") job.progress = ProgressMode::Bar;
    else if (args.progress == "json") job.progress = ProgressMode::Json;
    else if (args.progress == "none") job.progress = ProgressMode::Off;
    else throw UsageError("unknown --progress '" + args.progress + "'; use bar, json or none");
    if (!(args.fps > 0 && args.fps <= 1e6)) throw UsageError("--fps must be a number of frames per second > 0");
    if (!std::isfinite(args.time) || args.time < -1e9 || args.time > 1e9) throw UsageError("--time must be a number of seconds");
}

// On a CPU implementation, unless the user chose a size or a budget: a smaller image and a time
// budget, said in one line.
void applyCpuDefaults(const gpu::Context& ctx, FrameJob& job) {
    const bool chosen = !job.progressLabel.empty();
    job.progressLabel = "render";
    if (chosen || ctx.info().type != VK_PHYSICAL_DEVICE_TYPE_CPU || job.timeLimit > 0) return;
    job.settings.width = kCpuWidth;
    job.settings.height = kCpuHeight;
    job.timeLimit = kCpuSeconds;
    if (!job.quiet)
        std::fprintf(stderr,
                     "penumbra: %s runs Vulkan on the CPU, so this render is %ux%u with up to %u spp in about %.0f s "
                     "(choose with --width, --height, --spp or --time-limit)\n",
                     ctx.info().name.c_str(), kCpuWidth, kCpuHeight, job.settings.samplesPerPixel, kCpuSeconds);
}

std::filesystem::path defaultOutput(const RenderArgs& args, bool sequence) {
    if (!args.output.empty()) return args.output;
    std::string stem = std::filesystem::path(args.scene).stem().string();
    if (!args.map.empty()) stem += "-" + args.map;
    const char* suffix = !args.walk.empty() ? ".mp4" : sequence ? "_%04d.png" : ".png";
    std::filesystem::path output = std::filesystem::path("out") / (stem + suffix);
    std::error_code ec;
    std::filesystem::create_directories(output.parent_path(), ec);  // our own default folder
    return output;
}

void printSummary(const Scene& scene, const FrameJob& job, const gpu::Context& ctx, const FrameOutcome& r,
                  const std::filesystem::path& output) {
    const RenderStats& st = r.stats;
    if (st.invalidSamples)
        std::fprintf(stderr, "penumbra: warning: %llu path samples were NaN or infinite and were dropped\n",
                     static_cast<unsigned long long>(st.invalidSamples));
    if (job.quiet) return;
    const double rays = double(st.closestRays + st.shadowRays), gpuSeconds = st.gpuMilliseconds * 1e-3;
    std::string why = r.reason == StopReason::TimeLimit ? ", time limit reached" : "";
    if (job.adaptive.enabled())
        why += ", adaptive: " + std::to_string(int(100 * r.sampledFraction + 0.5)) + "% of the samples traced";
    std::fprintf(stderr, "penumbra: %s %ux%u, %u spp%s, %s, in %.2f s (GPU %.2f s), %.1f Mrays/s -> %s\n",
                 scene.name.c_str(), job.settings.width, job.settings.height, r.samplesPerPixel, why.c_str(),
                 ctx.info().name.c_str(), r.seconds, gpuSeconds, gpuSeconds > 0 ? rays / gpuSeconds * 1e-6 : 0.0,
                 output.string().c_str());
}

// A walk (--walk) or a video output: the flags that go with frames into one output, checked,
// and the walk read (a bad file is one line before any device opens). None for other renders.
std::optional<VideoJob> videoJob(const RenderArgs& args, const CLI::App& cmd, const std::filesystem::path& output) {
    const bool walk = !args.walk.empty(), video = isVideoPath(output);
    if (!walk && !video) {
        if (args.viewerQuality) throw UsageError("--viewer-quality renders walks and videos: add --walk FILE");
        return std::nullopt;
    }
    if (video && !walk && args.frames.empty())
        throw UsageError("a video needs frames: --walk FILE (a walk's camera path) or --frames A..B");
    if (walk && !args.frames.empty()) throw UsageError("--walk renders the walk's own frames: leave out --frames");
    if (!args.resume.empty() || args.checkpointSeconds > 0)
        throw UsageError("walks and videos cannot be checkpointed or resumed (--checkpoint, --resume)");
    if (!args.aovs.empty()) throw UsageError("--aov writes EXR layers of one image, not of walks and videos");
    if (args.mpi) throw UsageError("walks and videos render on one device: leave out --mpi");
    VideoJob job;
    job.fps = args.fps;
    job.offsetSeconds = args.time;
    job.viewerQuality = args.viewerQuality;
    job.phantom = args.phantom;
    if (args.viewerQuality) {
        job.samplesPerFrame = cmd.count("--spp") ? args.settings.samplesPerPixel : 1;
        if (job.samplesPerFrame < 1 || job.samplesPerFrame > 64)
            throw UsageError("with --viewer-quality, --spp is samples a frame: between 1 and 64");
        if (!video && formatFromPath(output) != ImageFormat::Png)
            throw UsageError("--viewer-quality frames are display-ready: write a video or .png images");
    }
    if (walk) {
        job.walk = viewer::loadInputScript(args.walk, "--walk");
        job.walkName = args.walk;
    } else {
        job.frames = parseFrames(args.frames);
    }
    (void)videoFrameCount(job);  // a walk too long is a UsageError now, not after loading the scene
    return job;
}

// Everything before rendering: the scene, the checked job, the output, the device. writesOutput:
// whether this process writes the output (a rank other than 0 of a single image does not).
RenderPlan prepareRender(const RenderArgs& args, const CLI::App& cmd, const std::string& device, bool writesOutput) {
    LoadedRender loaded = loadRender(args, cmd);
    RenderPlan plan{std::move(loaded.scene), std::move(loaded.job)};
    FrameJob& job = plan.job;
    applyFrameOptions(args, job);
    plan.sequence = !args.frames.empty();
    plan.frames = plan.sequence ? parseFrames(args.frames) : FrameRange{};
    plan.output = defaultOutput(args, plan.sequence);
    const std::filesystem::path& output = plan.output;
    // Fail before rendering, not after: a bad name or folder would waste the whole render.
    plan.video = videoJob(args, cmd, output);
    // --no-phantom: a walk's replay switches the phantom as the viewer does (H in the walk too);
    // every other render has it parked here, before its moments are placed.
    if (!args.phantom && !(plan.video && plan.video->walk)) PhantomSwitch(plan.scene).set(plan.scene, false, args.time);
    const bool video = isVideoPath(output);
    if (!video) formatFromPath(output);
    std::error_code ec;
    if (!plan.sequence && !args.resume.empty() && !std::filesystem::is_regular_file(args.resume, ec))
        throw Error("--resume " + args.resume + ": no such checkpoint file (it is OUTPUT.state, written by --checkpoint "
                    "or when a render is interrupted)");
    if (plan.sequence && !args.resume.empty() && args.resume != output.string())
        throw UsageError("with --frames, --resume takes the output pattern ('" + output.string() + "')");
    if (writesOutput) {
        checkWritable(plan.sequence && !video ? framePath(output, 0) : output);
        if (job.aovs.any()) checkWritable(aovPathFor(output));
    }
    plan.ctx = openDevice(device);
    applyCpuDefaults(*plan.ctx, job);
    validateSettings(job.settings);
    plan.sequenceOptions = SequenceOptions{plan.frames, args.fps, args.time, !args.resume.empty()};
    return plan;
}

void runRender(const RenderArgs& args, const CLI::App& cmd) {
    if (std::unique_ptr<distributed::Comm> comm = startRanks(args.mpi)) {
        if (!args.walk.empty() || isVideoPath(args.output))
            throw UsageError("walks and videos render on one device, not across MPI ranks");
        renderOnRanks(*comm, args, [&](const std::string& device, bool writesOutput) {
            return prepareRender(args, cmd, device, writesOutput);
        });
        return;
    }
    RenderPlan plan = prepareRender(args, cmd, args.device, true);
    if (plan.video) {
        renderVideo(*plan.ctx, plan.scene, plan.job, plan.output, *plan.video);
        return;
    }
    if (plan.sequence) {
        renderSequence(*plan.ctx, plan.scene, plan.job, plan.output, plan.sequenceOptions);
        return;
    }
    applySceneTime(plan.scene, args.time);
    plan.job.settings.time = textureTime(args.time);
    std::optional<std::filesystem::path> resumeFrom;
    if (!args.resume.empty()) resumeFrom = args.resume;
    const FrameOutcome r = renderFrame(*plan.ctx, plan.scene, plan.job, plan.output, resumeFrom);
    printSummary(plan.scene, plan.job, *plan.ctx, r, plan.output);
}

}  // namespace

void registerRender(CLI::App& app, Action& action) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "render a scene to a PNG (tone mapped) or EXR (linear HDR) file");
    addRenderOptions(*cmd, *args);
    cmd->callback([args, cmd, &action] { action = [args, cmd] { runRender(*args, *cmd); }; });
}

}  // namespace penumbra::app
