// One final frame: render under the job's budget (samples, time, signals), with checkpoints
// and resuming, then write the outputs.
#pragma once

#include <filesystem>
#include <optional>

#include "app/render_options.h"
#include "gpu/context.h"
#include "render/progressive.h"
#include "scene/scene.h"

namespace penumbra::app {

struct FrameOutcome {
    StopReason reason = StopReason::Samples;
    std::uint32_t samplesPerPixel = 0;  // nominal, reached
    double seconds = 0;                 // wall clock of this run (a resumed render: since resuming)
    double sampledFraction = 1;         // samples traced / nominal (adaptive sampling's saving)
    RenderStats stats;
};

// Renders `scene` (already at its moment) to `output`. resumeFrom: a state file to continue.
// On SIGINT/SIGTERM: writes the image so far and the state file, then throws Interrupted.
FrameOutcome renderFrame(const gpu::Context& ctx, const Scene& scene, const FrameJob& job,
                         const std::filesystem::path& output,
                         const std::optional<std::filesystem::path>& resumeFrom);

}  // namespace penumbra::app
