// Image sequences (--frames A..B): one frame per moment frame / fps + offset, each its own file.
#pragma once

#include <filesystem>
#include <string>

#include "app/render_frame.h"
#include "app/render_options.h"
#include "gpu/context.h"
#include "scene/scene.h"

namespace penumbra::app {

// The file of frame `frame`: printf's %d or %0Nd in the pattern's file name is replaced by the
// frame number; without one, "_%04d" goes before the extension (out/a.png -> out/a_0007.png).
// UsageError for any other % directive or more than one frame number.
std::filesystem::path framePath(const std::filesystem::path& pattern, std::int64_t frame);

struct SequenceOptions {
    FrameRange frames;
    double fps = 24;
    double offsetSeconds = 0;
    bool resume = false;  // skip finished frames, continue interrupted ones
};

// Whether --resume skips frame `frame`: its image was written (atomically) and no state file
// beside it says it was interrupted.
bool frameFinished(const std::filesystem::path& pattern, std::int64_t frame);

// Renders one frame of the sequence (moving `scene` to its moment), continuing it from its state
// file when resuming and one is there.
FrameOutcome renderSequenceFrame(const gpu::Context& ctx, Scene& scene, const FrameJob& job,
                                 const std::filesystem::path& pattern, const SequenceOptions& options,
                                 std::int64_t frame);

// Renders the frames in order; `scene` is moved to each frame's moment in place.
void renderSequence(const gpu::Context& ctx, Scene& scene, const FrameJob& job, const std::filesystem::path& pattern,
                    const SequenceOptions& options);

}  // namespace penumbra::app
