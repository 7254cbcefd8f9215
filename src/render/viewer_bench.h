// The viewer's whole frame, headless: InteractiveRenderer driven frame after frame with a
// scripted camera, timed with GPU timestamps per pass (`penumbra bench --viewer`).
#pragma once

#include <map>
#include <optional>
#include <string>

#include "image/image.h"
#include "render/interactive_renderer.h"

namespace penumbra {

enum class CameraMotion { Static, Orbit, Walk };
CameraMotion parseCameraMotion(const std::string& name);  // "static" | "orbit" | "walk"; UsageError otherwise
const char* cameraMotionName(CameraMotion motion);

// The camera `seconds` into a scripted motion that starts at `start`:
//   orbit: circles the look-at point at the starting distance, one turn every 12 s;
//   walk:  walks along the view direction at 1.4 m/s with a gentle side-to-side look (a
//          person walking through a level; it may pass through walls, which is fine for timing).
Camera cameraInMotion(const Camera& start, CameraMotion motion, double seconds);

struct ViewerBenchOptions {
    std::uint32_t width = 1280, height = 800;
    ViewSettings view;  // spp, bounces, temporal, denoiser, torch
    bool cullBackfaces = false;  // InteractiveRenderer::setCullBackfaces
    BvhBuild bvhBuild = BvhBuild::Cpu;  // where the scene's tree is built (bench --viewer --bvh-build)
    CameraMotion motion = CameraMotion::Static;
    double frameSeconds = 1.0 / 60.0;  // scripted time per frame (the motion does not depend on speed)
    int frames = 200;                  // timed frames (medians over these)
    int warmupFrames = 30;             // at least this many untimed frames ...
    double warmupSeconds = 1.5;        // ... and at least this long, so clocks settle
    // Equal-time error: when set, frames run (after the warm-up, from a fresh history) until their
    // summed GPU frame time reaches budgetMs, and the images are compared with the reference.
    std::optional<ImageRgb> reference;
    double budgetMs = 0;
    // The error of one such run is heavy-tailed (a firefly in the last frames doubles it), so it
    // can be measured this many times, each from a fresh history with new random numbers, and
    // the means reported.
    int errorTrials = 1;
    // Instead of budgetMs: exactly this many frames per trial, so that builds which differ only
    // after the trace (the denoiser) filter the same images.
    int budgetFrameCount = 0;
    // A Doom level: every door, lift, floor and crusher moves on the script's clock (fired again
    // once all have stopped), so the frames include the moving sectors' top-level uploads.
    bool moveSectors = false;
    // The camera of the error's frames: still (the default), or moving along a scripted motion
    // that arrives at the scene's camera on the last frame (frame k of n at time (k - n + 1) *
    // frameSeconds), so the same reference judges a frame seen in motion.
    CameraMotion errorMotion = CameraMotion::Static;
};

struct ViewerBenchResult {
    double frameMs = 0;                    // median of the whole frame's GPU time
    std::map<std::string, double> passMs;  // median GPU time per pass that ran
    double raysPerPixelPerSample = 0;      // mean over the timed frames
    double mraysPerSecond = 0;             // rays of the median frame over its trace time
    int frames = 0;
    // Equal-time error (only with a reference): relative MSE of the raw running mean and of the
    // denoised image, and how many frames fitted in the budget (means over the trials).
    std::optional<double> relMseRaw, relMseDenoised;
    int budgetFrames = 0;
    // The trace kernel as compiled: what it was specialised for and the driver's statistics.
    std::string kernelFeatures;
    std::vector<gpu::PipelineStatistic> traceStatistics;
    std::vector<gpu::PipelineStatistic> imageStatistics;  // temporal and a-trous
};

ViewerBenchResult runViewerBench(const gpu::Context& ctx, const Scene& scene, bool torchIsLastLight,
                                 const ViewerBenchOptions& options);

// Relative MSE (Rousselle et al.): mean over pixels and channels of (x - r)^2 / (r^2 + 0.01).
double relativeMse(const ImageRgb& image, const ImageRgb& reference);

}  // namespace penumbra
