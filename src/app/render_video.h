// Frames made one after another into one output (docs/RENDERING.md, "Walks and videos"): a walk's
// camera path (--walk FILE, the viewer's --script format) or an animation's moments (--frames to
// a video), each frame at final-frame quality or at the viewer's settings (--viewer-quality),
// into an H.264 video (.mp4, .mkv, .mov; written whole or not at all) or an image sequence.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "app/render_options.h"
#include "gpu/context.h"
#include "interact/input_script.h"
#include "scene/scene.h"

namespace penumbra::app {

struct VideoJob {
    // The walk to replay; none: the moments of --frames (first..last at frame / fps + offset).
    std::optional<std::vector<viewer::ScriptEvent>> walk;
    std::string walkName;  // the file, for messages
    FrameRange frames;
    double fps = 24;
    double offsetSeconds = 0;
    // The viewer's renderer (temporal accumulation, its denoiser) at samplesPerFrame per frame,
    // instead of a final render of job.settings.samplesPerPixel per frame.
    bool viewerQuality = false;
    std::uint32_t samplesPerFrame = 1;
    bool phantom = true;  // a walk starts with the dungeon's phantom on (H in the walk toggles it)
};

// The number of frames the job renders.
std::uint64_t videoFrameCount(const VideoJob& video);

// Renders every frame into `output`: a video when isVideoPath(output), else images named by
// framePath(output, frame). On SIGINT/SIGTERM the frame in progress ends, a video is not written
// at all (its temporary file is removed), images written so far stay; then Interrupted.
void renderVideo(const gpu::Context& ctx, Scene& scene, const FrameJob& job, const std::filesystem::path& output,
                 const VideoJob& video);

}  // namespace penumbra::app
