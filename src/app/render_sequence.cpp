#include "app/render_sequence.h"

#include <cstdio>

#include "core/error.h"
#include "scene/animation.h"

namespace penumbra::app {
namespace {

// The position and width of the one frame-number directive in `name` ("%d", "%04d"), if any.
struct Directive {
    std::size_t at = std::string::npos, length = 0;
    int width = 0;
};

Directive findDirective(const std::string& name) {
    Directive d;
    for (std::size_t i = 0; i < name.size(); ++i) {
        if (name[i] != '%') continue;
        std::size_t j = i + 1;
        int width = 0;
        while (j < name.size() && std::isdigit(static_cast<unsigned char>(name[j])) && j - i < 4) width = width * 10 + (name[j++] - '0');
        if (j >= name.size() || name[j] != 'd' || width > 12)
            throw UsageError("output name '" + name + "': only %d or %0Nd (the frame number) may follow a %");
        if (d.at != std::string::npos) throw UsageError("output name '" + name + "' has more than one frame number");
        d = Directive{i, j + 1 - i, width};
        i = j;
    }
    return d;
}

}  // namespace

std::filesystem::path framePath(const std::filesystem::path& pattern, std::int64_t frame) {
    const std::string name = pattern.filename().string();
    const Directive d = findDirective(name);
    char number[32];
    std::snprintf(number, sizeof number, "%0*lld", d.at == std::string::npos ? 4 : d.width, static_cast<long long>(frame));
    if (d.at == std::string::npos)
        return pattern.parent_path() / (pattern.stem().string() + "_" + number + pattern.extension().string());
    return pattern.parent_path() / (name.substr(0, d.at) + number + name.substr(d.at + d.length));
}

bool frameFinished(const std::filesystem::path& pattern, std::int64_t frame) {
    const std::filesystem::path output = framePath(pattern, frame);
    std::error_code ec;
    // A frame's image is written atomically, so an image without a state beside it is finished.
    return !std::filesystem::exists(statePathFor(output), ec) && std::filesystem::exists(output, ec);
}

FrameOutcome renderSequenceFrame(const gpu::Context& ctx, Scene& scene, const FrameJob& job,
                                 const std::filesystem::path& pattern, const SequenceOptions& o, std::int64_t frame) {
    const std::filesystem::path output = framePath(pattern, frame);
    const std::filesystem::path state = statePathFor(output);
    std::error_code ec;
    const bool haveState = std::filesystem::exists(state, ec);
    applySceneTime(scene, double(frame) / o.fps + o.offsetSeconds);
    FrameJob frameJob = job;
    frameJob.settings.time = textureTime(double(frame) / o.fps + o.offsetSeconds);
    frameJob.progressLabel = "frame " + std::to_string(frame);
    frameJob.resumeArgument = pattern.string();  // a sequence resumes by its output pattern
    const std::optional<std::filesystem::path> resumeFrom =
        o.resume && haveState ? std::optional<std::filesystem::path>(state) : std::nullopt;
    return renderFrame(ctx, scene, frameJob, output, resumeFrom);
}

void renderSequence(const gpu::Context& ctx, Scene& scene, const FrameJob& job, const std::filesystem::path& pattern,
                    const SequenceOptions& o) {
    const std::int64_t count = o.frames.last - o.frames.first + 1;
    std::int64_t skipped = 0;
    for (std::int64_t frame = o.frames.first; frame <= o.frames.last; ++frame) {
        if (o.resume && frameFinished(pattern, frame)) {
            ++skipped;
            continue;
        }
        const FrameOutcome r = renderSequenceFrame(ctx, scene, job, pattern, o, frame);
        if (!job.quiet)
            std::fprintf(stderr, "penumbra: frame %lld (%lld of %lld) at t = %.4g s: %u spp in %.2f s -> %s\n",
                         static_cast<long long>(frame), static_cast<long long>(frame - o.frames.first + 1),
                         static_cast<long long>(count), double(frame) / o.fps + o.offsetSeconds, r.samplesPerPixel,
                         r.seconds, framePath(pattern, frame).string().c_str());
    }
    if (skipped && !job.quiet)
        std::fprintf(stderr, "penumbra: %lld finished frames were skipped (--resume)\n", static_cast<long long>(skipped));
}

}  // namespace penumbra::app
