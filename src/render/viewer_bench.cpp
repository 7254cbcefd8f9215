#include "render/viewer_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <vector>

#include "core/error.h"
#include "core/median.h"
#include "gpu/buffer.h"
#include "render/kernel_features.h"
#include "scene/doom/level.h"
#include "scene/animation.h"
#include "shared/constants.h"

namespace penumbra {
namespace {


// v turned by `radians` about the unit axis (Rodrigues' formula).
Vec3 rotateAbout(Vec3 v, Vec3 axis, double radians) {
    const float c = float(std::cos(radians)), s = float(std::sin(radians));
    return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1.0f - c));
}

void renderFrame(InteractiveRenderer& renderer, const Camera& camera, const ViewSettings& view) {
    renderer.commands().run([&](VkCommandBuffer cmd) { renderer.record(cmd, camera, view); });
    renderer.finishFrame();
}

ImageRgb imageFromHistory(const gpu::Context& ctx, InteractiveRenderer& r) {
    auto texels = gpu::downloadBuffer<shader::HistoryTexel>(ctx, r.commands(), r.history(),
                                                            std::size_t(r.width()) * r.height());
    ImageRgb image(int(r.width()), int(r.height()));
    for (std::size_t i = 0; i < texels.size(); ++i) image.pixels[i] = texels[i].color;
    return image;
}

ImageRgb imageFromVec4(const gpu::Context& ctx, InteractiveRenderer& r, const gpu::Buffer& buffer) {
    auto texels = gpu::downloadBuffer<Vec4>(ctx, r.commands(), buffer, std::size_t(r.width()) * r.height());
    ImageRgb image(int(r.width()), int(r.height()));
    for (std::size_t i = 0; i < texels.size(); ++i) image.pixels[i] = {texels[i].x, texels[i].y, texels[i].z};
    return image;
}

// Frames from a fresh history until their GPU time reaches the budget (or their count is
// reached), then the raw running mean and the denoised image against the reference; means over
// the trials. The camera is still, or moves along o.errorMotion to arrive at `camera` last.
void measureEqualTimeError(const gpu::Context& ctx, InteractiveRenderer& renderer, const Camera& camera,
                           const ViewerBenchOptions& o, ViewerBenchResult& result) {
    if (!o.reference->sameSize(ImageRgb(int(o.width), int(o.height))))
        throw UsageError("the reference image is " + std::to_string(o.reference->width) + "x" +
                         std::to_string(o.reference->height) + ", the bench renders " + std::to_string(o.width) +
                         "x" + std::to_string(o.height) + "; render the reference at the bench's size");
    const int trials = std::max(o.errorTrials, 1);
    double raw = 0, denoised = 0, frames = 0;
    for (int trial = 0; trial < trials; ++trial) {
        renderer.resetHistory();  // the random numbers go on: every trial sees new ones
        double spent = 0;
        int n = 0;
        while (o.budgetFrameCount > 0 ? n < o.budgetFrameCount : spent < o.budgetMs || n == 0) {
            const double t = o.budgetFrameCount > 0 ? (n - o.budgetFrameCount + 1) * o.frameSeconds : 0.0;
            renderFrame(renderer, cameraInMotion(camera, o.errorMotion, t), o.view);
            spent += renderer.stats().passMilliseconds[std::size_t(ViewerPass::Frame)];
            ++n;
            if (n > 1000000) break;  // a device without timestamps reports -1 ms
        }
        frames += n;
        raw += relativeMse(imageFromHistory(ctx, renderer), *o.reference);
        if (renderer.denoised()) denoised += relativeMse(imageFromVec4(ctx, renderer, *renderer.denoised()), *o.reference);
    }
    result.budgetFrames = int(std::lround(frames / trials));
    result.relMseRaw = raw / trials;
    if (renderer.denoised()) result.relMseDenoised = denoised / trials;
}

}  // namespace

CameraMotion parseCameraMotion(const std::string& name) {
    if (name == "static") return CameraMotion::Static;
    if (name == "orbit") return CameraMotion::Orbit;
    if (name == "walk") return CameraMotion::Walk;
    throw UsageError("--camera-motion must be static, orbit or walk, not '" + name + "'");
}

const char* cameraMotionName(CameraMotion motion) {
    switch (motion) {
        case CameraMotion::Orbit: return "orbit";
        case CameraMotion::Walk: return "walk";
        default: return "static";
    }
}

Camera cameraInMotion(const Camera& start, CameraMotion motion, double seconds) {
    Camera c = start;
    const Vec3 up = normalize(start.up);
    if (motion == CameraMotion::Orbit) {
        c.position = start.lookAt + rotateAbout(start.position - start.lookAt, up, 2 * kPi * seconds / 12.0);
    } else if (motion == CameraMotion::Walk) {
        const Vec3 view = start.lookAt - start.position;
        Vec3 ahead = view - up * dot(view, up);
        ahead = length(ahead) > 0 ? normalize(ahead) : normalize(view);
        c.position = start.position + ahead * float(1.4 * seconds);
        const Vec3 look = rotateAbout(view, up, 0.15 * std::sin(2 * kPi * seconds / 4.0));
        c.lookAt = c.position + look;
    }
    return c;
}

double relativeMse(const ImageRgb& image, const ImageRgb& reference) {
    if (!image.sameSize(reference)) throw Error("relative MSE of images of different sizes");
    double sum = 0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const double r = reference.pixels[i][k], d = double(image.pixels[i][k]) - r;
            sum += d * d / (r * r + 0.01);
        }
    return image.pixels.empty() ? 0.0 : sum / (3.0 * double(image.pixels.size()));
}

ViewerBenchResult runViewerBench(const gpu::Context& ctx, const Scene& scene, bool torchIsLastLight,
                                 const ViewerBenchOptions& o) {
    if (o.frames < 1 || o.frames > 100000) throw UsageError("--frames must be between 1 and 100000");
    if (o.errorMotion != CameraMotion::Static && o.budgetFrameCount < 1)
        throw UsageError("--error-camera-motion needs --budget-frames (the motion ends on the reference's view)");
    InteractiveRenderer renderer(ctx, scene, torchIsLastLight, 1, o.bvhBuild);
    renderer.setCullBackfaces(o.cullBackfaces);
    renderer.resize(o.width, o.height);
    double scriptTime = 0;
    // Animated instances (the dungeon's phantom, glTF animations) move on the same clock, so the
    // timed frames include their top-level upload and object motion.
    std::optional<Scene> moving;
    if (animatesGeometry(scene) || (o.moveSectors && scene.doomLevel)) moving = scene;
    std::optional<doom::Level> level, started;
    int ticked = 0;
    if (o.moveSectors && scene.doomLevel) started = level = doom::withEverythingMoving(*scene.doomLevel);
    auto nextCamera = [&] {
        Camera c = cameraInMotion(scene.camera, o.motion, scriptTime);
        if (moving) {
            if (animatesGeometry(scene)) applyInstanceAnimations(*moving, scriptTime);
            if (level) {
                const int due = int(scriptTime * doom::kTicsPerSecond);
                ticked = std::min(ticked, due);  // the timed frames start the script again
                for (; ticked < due; ++ticked) {
                    level->tic(std::nullopt);
                    if (level->activeMovers() == 0) level = started;
                }
                doom::placePlaneInstances(*level, moving->instances);
            }
            renderer.setInstanceTransforms(*moving);
        }
        scriptTime += o.frameSeconds;
        return c;
    };
    const auto warmStart = std::chrono::steady_clock::now();
    for (int k = 0; k < o.warmupFrames ||
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - warmStart).count() < o.warmupSeconds;
         ++k)
        renderFrame(renderer, nextCamera(), o.view);
    // The timed frames follow the script from its start, however many frames the warm-up took, so
    // that two runs of a moving camera time the same views.
    scriptTime = 0;

    std::vector<double> frameMs;
    std::map<std::string, std::vector<double>> passMs;
    std::vector<double> mrays;
    double raysPerSample = 0;
    const double samples = double(o.width) * o.height * o.view.samplesPerFrame;
    for (int k = 0; k < o.frames; ++k) {
        renderFrame(renderer, nextCamera(), o.view);
        const ViewerStats& st = renderer.stats();
        // A still view's frames reuse its G-buffer: their G-buffer pass costs nothing.
        if (st.gbufferSkipped) passMs[viewerPassName(ViewerPass::GBuffer)].push_back(0.0);
        // Denoised with no debug view, the denoiser's last pass tone-maps: no tonemap pass of its own.
        if (st.tonemapInDenoiser) passMs[viewerPassName(ViewerPass::Tonemap)].push_back(0.0);
        for (std::uint32_t p = 0; p < std::uint32_t(ViewerPass::Count); ++p) {
            if (st.passMilliseconds[p] <= 0) continue;
            if (ViewerPass(p) == ViewerPass::Frame) frameMs.push_back(st.passMilliseconds[p]);
            else passMs[viewerPassName(ViewerPass(p))].push_back(st.passMilliseconds[p]);
        }
        mrays.push_back(st.raysPerSecond * 1e-6);
        raysPerSample += double(st.rays) / samples;
    }
    ViewerBenchResult result;
    result.kernelFeatures = kernelSpecNames(renderer.kernelSpec());
    result.traceStatistics = renderer.traceStatistics();
    result.imageStatistics = renderer.imageStatistics();
    result.frames = o.frames;
    result.frameMs = median(frameMs);
    for (auto& [name, values] : passMs) result.passMs[name] = median(values);
    for (auto& [name, ms] : renderer.traceStageMilliseconds()) result.passMs["trace." + name] = ms;
    result.mraysPerSecond = median(mrays);
    result.raysPerPixelPerSample = raysPerSample / o.frames;
    if (o.reference) measureEqualTimeError(ctx, renderer, scene.camera, o, result);
    return result;
}

}  // namespace penumbra
