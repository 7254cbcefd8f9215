#include "app/render_video.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/render_sequence.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/progress.h"
#include "gpu/buffer.h"
#include "image/video_writer.h"
#include "image/write.h"
#include "interact/walk_replay.h"
#include "render/final_passes.h"
#include "render/interactive_renderer.h"
#include "render/progressive.h"
#include "scene/animation.h"
#include "scene/instances.h"

namespace penumbra::app {
namespace {

using viewer::WorldChange;

// One frame's pixels: display-ready sRGB, and the linear image when the renderer has it (final
// quality: image sequences in EXR keep the radiance).
struct RenderedFrame {
    ImageRgb linear;
    std::vector<std::uint8_t> rgb;
};

// What moves between frames: a walk's camera (and the world through playStep), or the scene's
// own animation.
class FrameSource {
public:
    virtual ~FrameSource() = default;
    // Moves the scene (and the camera) to the next frame.
    virtual WorldChange next(Scene& scene) = 0;
    virtual Camera camera(const Scene& scene) const = 0;
    virtual double seconds() const = 0;  // the frame's moment: animated textures show it
};

class WalkSource final : public FrameSource {
public:
    WalkSource(const Scene& scene, const VideoJob& video)
        : replay_(scene, *video.walk, 1.0 / video.fps, video.phantom) {}
    WorldChange next(Scene& scene) override { return replay_.nextFrame(scene); }
    Camera camera(const Scene&) const override { return replay_.camera(); }
    double seconds() const override { return replay_.clock(); }

private:
    viewer::WalkReplay replay_;
};

class MomentSource final : public FrameSource {
public:
    explicit MomentSource(const VideoJob& video) : video_(video), frame_(video.frames.first - 1) {}
    WorldChange next(Scene& scene) override {
        ++frame_;
        applySceneTime(scene, seconds());
        return WorldChange{animatesGeometry(scene), false};
    }
    Camera camera(const Scene& scene) const override { return scene.camera; }
    double seconds() const override { return double(frame_) / video_.fps + video_.offsetSeconds; }

private:
    const VideoJob& video_;
    std::int64_t frame_;
};

// Makes a frame of the scene as it now stands.
class FrameMaker {
public:
    virtual ~FrameMaker() = default;
    virtual RenderedFrame make(const Scene& scene, const Camera& camera, double seconds, WorldChange change) = 0;
    virtual std::uint32_t samplesPerFrame() const = 0;
};

// Instances of emissive prototypes are baked into the world where they stand (scene/instances.h):
// moving one takes a new Renderer.
bool hasBakedInstances(const Scene& scene) {
    return std::any_of(scene.instances.begin(), scene.instances.end(), [&](const Instance& i) {
        return i.prototype < scene.prototypes.size() && prototypeIsEmissive(scene, scene.prototypes[i.prototype]);
    });
}

// The render command's final frame: job.settings.samplesPerPixel (under --time-limit per frame,
// --noise-threshold, --denoise). One renderer and one set of denoising passes for every frame:
// moved instances (doors, lifts) and changed sector lights are updated in place; only changed
// geometry makes a new renderer.
class FinalFrames final : public FrameMaker {
public:
    FinalFrames(const gpu::Context& ctx, const FrameJob& job) : ctx_(ctx), job_(job) {}
    RenderedFrame make(const Scene& scene, const Camera& camera, double seconds, WorldChange change) override {
        update(scene, change);
        renderer_->restart(camera, textureTime(seconds));
        ProgressiveRender render(*renderer_, job_.adaptive);
        RenderBudget budget;
        budget.samplesPerPixel = job_.settings.samplesPerPixel;
        budget.seconds = job_.timeLimit;
        budget.stop = &StopOnSignals::signal();
        render.run(budget);
        RenderedFrame frame;
        frame.linear = job_.denoise ? denoise(render) : render.image();
        frame.rgb = toneMapToSrgb8(frame.linear, job_.toneMap);
        return frame;
    }
    std::uint32_t samplesPerFrame() const override { return job_.settings.samplesPerPixel; }

private:
    void update(const Scene& scene, const WorldChange& change) {
        if (!renderer_ || change.geometryChanged || (change.instancesMoved && hasBakedInstances(scene))) {
            passes_.reset();  // it refers to the renderer
            renderer_ = std::make_unique<Renderer>(ctx_, scene, job_.settings);
            return;
        }
        if (change.instancesMoved) renderer_->setInstanceTransforms(scene);
        // A flickering sector changes its light nearly every tic: no new renderer for that.
        for (std::uint32_t m : change.lightsChanged) renderer_->setUnsampledEmission(m, scene.materials[m].emission);
        // A switch turned or a key was taken: sent up in place (a new renderer has them already).
        for (std::uint32_t m : change.materialsChanged) renderer_->setMaterial(m, scene.materials[m]);
    }
    ImageRgb denoise(ProgressiveRender& render) {
        if (!passes_) passes_ = std::make_unique<FinalFramePasses>(ctx_, *renderer_);
        passes_->restart();  // this frame's view and instances
        return passes_->denoise(render.current());
    }

    const gpu::Context& ctx_;
    const FrameJob& job_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<FinalFramePasses> passes_;  // after the renderer: destroyed first
};

// The viewer's frame (render/interactive_renderer.h), history carried from frame to frame as in
// the window: what a screen recording of `penumbra view --script --fixed-dt` would show.
class ViewerFrames final : public FrameMaker {
public:
    ViewerFrames(const gpu::Context& ctx, const Scene& scene, const ViewSettings& settings, std::uint32_t width,
                 std::uint32_t height)
        : ctx_(ctx), renderer_(ctx, scene, true), settings_(settings) {
        renderer_.resize(width, height);
    }
    RenderedFrame make(const Scene& scene, const Camera& camera, double seconds, WorldChange change) override {
        if (change.geometryChanged) renderer_.rebuildScene(scene, true);
        else if (change.instancesMoved) renderer_.setInstanceTransforms(scene);
        for (std::uint32_t m : change.lightsChanged) renderer_.setUnsampledEmission(m, scene.materials[m].emission);
        for (std::uint32_t m : change.materialsChanged) renderer_.setMaterial(m, scene.materials[m]);
        settings_.time = textureTime(seconds);
        renderer_.commands().run([&](VkCommandBuffer cmd) { renderer_.record(cmd, camera, settings_); });
        renderer_.finishFrame();
        const std::size_t pixels = std::size_t(renderer_.width()) * renderer_.height();
        const std::vector<std::uint32_t> rgba =
            gpu::downloadBuffer<std::uint32_t>(ctx_, renderer_.commands(), renderer_.display(), pixels);
        RenderedFrame frame;
        frame.rgb.resize(pixels * 3);
        for (std::size_t i = 0; i < pixels; ++i)
            for (int c = 0; c < 3; ++c) frame.rgb[3 * i + c] = std::uint8_t(rgba[i] >> (8 * c));
        return frame;
    }
    std::uint32_t samplesPerFrame() const override { return settings_.samplesPerFrame; }

private:
    const gpu::Context& ctx_;
    InteractiveRenderer renderer_;
    ViewSettings settings_;
};

// Where the frames go: one video, written whole or not at all, or one image per frame.
class FrameSink {
public:
    FrameSink(const std::filesystem::path& output, const FrameJob& job, const VideoJob& video)
        : output_(output), job_(job) {
        if (!isVideoPath(output)) return;
        file_.emplace(output);
        writer_.emplace(file_->tmp(), output,
                        VideoSettings{job.settings.width, job.settings.height, video.fps, VideoSettings{}.crf});
    }
    bool video() const { return writer_.has_value(); }
    void add(std::int64_t frameNumber, const RenderedFrame& frame) {
        if (writer_) return writer_->addFrame(frame.rgb);
        const std::filesystem::path path = framePath(output_, frameNumber);
        if (!frame.linear.empty()) writeImage(path, frame.linear, job_.toneMap);
        else writePngRgb8(path, int(job_.settings.width), int(job_.settings.height), frame.rgb);
    }
    void finish() {
        if (!writer_) return;
        writer_->finish();
        file_->commit();
    }

private:
    std::filesystem::path output_;
    const FrameJob& job_;
    std::optional<PendingFile> file_;  // declared before the writer: the writer closes first
    std::optional<VideoWriter> writer_;
};

ViewSettings viewerSettings(Scene& scene, const FrameJob& job, const VideoJob& video) {
    ViewSettings settings;
    settings.samplesPerFrame = video.samplesPerFrame;
    settings.denoise = job.denoise;
    settings.exposure = job.toneMap.exposure;
    settings.apertureRadius = scene.camera.apertureRadius;
    settings.focusDistance = scene.camera.focusDistance;
    viewer::prepareSceneSettings(scene, settings);  // the torch and roulette, as the viewer has them
    return settings;
}

[[noreturn]] void throwInterrupted(int signal, std::uint64_t done, std::uint64_t total, bool video,
                                   const std::filesystem::path& output) {
    std::string what = std::string("interrupted by ") + StopOnSignals::signalName(signal) + " after " +
                       std::to_string(done) + " of " + std::to_string(total) + " frames; ";
    what += video ? "no video was written (" + output.string() + " is written whole or not at all)"
                  : "the frames before it are written";
    throw Interrupted(what, 128 + signal);
}

}  // namespace

std::uint64_t videoFrameCount(const VideoJob& video) {
    if (video.walk) return viewer::walkFrameCount(*video.walk, 1.0 / video.fps);
    return std::uint64_t(video.frames.last - video.frames.first + 1);
}

void renderVideo(const gpu::Context& ctx, Scene& scene, const FrameJob& job, const std::filesystem::path& output,
                 const VideoJob& video) {
    const std::uint64_t total = videoFrameCount(video);
    std::unique_ptr<FrameMaker> maker;
    if (video.viewerQuality)
        maker = std::make_unique<ViewerFrames>(ctx, scene, viewerSettings(scene, job, video), job.settings.width,
                                               job.settings.height);
    else
        maker = std::make_unique<FinalFrames>(ctx, job);
    std::unique_ptr<FrameSource> source;
    if (video.walk) source = std::make_unique<WalkSource>(scene, video);
    else source = std::make_unique<MomentSource>(video);
    FrameSink sink(output, job, video);

    std::optional<StopOnSignals> signals;
    if (job.stopOnSignals) signals.emplace();
    const auto start = std::chrono::steady_clock::now();
    std::optional<std::string> levelCompleted;  // a walk that ends a Doom level says so at the end
    {
        ProgressBar progress(video.walk ? "walk" : "video", total, job.quiet ? ProgressMode::Off : job.progress,
                             "frames");
        for (std::uint64_t i = 0; i < total; ++i) {
            const WorldChange change = source->next(scene);
            if (change.levelCompleted) levelCompleted = change.levelCompleted;
            const RenderedFrame frame = maker->make(scene, source->camera(scene), source->seconds(), change);
            // A frame cut short by the signal is not kept: every frame kept is a whole one.
            if (const int signal = StopOnSignals::signal().load()) throwInterrupted(signal, i, total, sink.video(), output);
            sink.add(video.walk ? std::int64_t(i) : video.frames.first + std::int64_t(i), frame);
            progress.update(i + 1);
        }
        sink.finish();
        progress.finish();
    }
    if (job.quiet) return;
    if (levelCompleted) std::fprintf(stderr, "penumbra: %s\n", levelCompleted->c_str());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "penumbra: %s: %llu frames %ux%u at %.4g fps (%s, %u spp a frame) in %.1f s -> %s\n",
                 video.walk ? video.walkName.c_str() : scene.name.c_str(), static_cast<unsigned long long>(total),
                 job.settings.width, job.settings.height, video.fps,
                 video.viewerQuality ? "viewer quality" : "final quality", maker->samplesPerFrame(), seconds,
                 output.string().c_str());
}

}  // namespace penumbra::app
