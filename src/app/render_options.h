// What `penumbra render` was asked to do: the flags as typed (RenderArgs), and the checked
// plan for each frame (FrameJob). render_command.cpp registers the flags; render_frame.cpp
// renders one frame; render_sequence.cpp loops over --frames.
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/common_options.h"
#include "core/progress.h"
#include "image/tonemap.h"
#include "render/adaptive.h"
#include "render/settings.h"
#include "scene/io/env_spec.h"

namespace penumbra::app {

struct RenderArgs {
    std::string scene = "cornell";
    std::string map;
    std::string output;  // default: out/<scene>.png (out/<scene>_%04d.png for --frames)
    std::string device;
    std::string accel = "bvh";
    std::string mis = "both";
    float exposure = 0;
    bool quiet = false;
    CameraOverrides camera;
    EnvironmentSpec env;
    WadOptions wad;
    RenderSettings settings;
    // Final-frame options (docs/RENDERING.md).
    std::string timeLimit;           // --time-limit DURATION
    float noiseThreshold = 0;        // --noise-threshold X
    double checkpointSeconds = 0;    // --checkpoint SECONDS
    std::string resume;              // --resume FILE
    bool denoise = false;            // --denoise
    std::vector<std::string> aovs;   // --aov albedo,normal,...
    std::string frames;              // --frames A..B
    double time = 0;                 // --time SECONDS: the scene's moment (sequences: the offset)
    double fps = 24;                 // --fps: frames per second of a sequence
    std::string progress = "bar";    // --progress bar|json|none
    bool mpi = false;                // --mpi: join an MPI job even when not started by mpirun
    std::string walk;                // --walk FILE: replay a walk (the viewer's --script format)
    bool viewerQuality = false;      // --viewer-quality: walks and videos at the viewer's settings
    bool phantom = true;             // --no-phantom: the dungeon's phantom switched off, as in view
};

// Which AOV layers to write.
struct AovSet {
    bool albedo = false, normal = false, depth = false, variance = false, samples = false;
    bool any() const { return albedo || normal || depth || variance || samples; }
    bool needsGuides() const { return albedo || normal || depth; }
};
AovSet parseAovs(const std::vector<std::string>& names);  // UsageError on an unknown name

struct FrameRange {
    std::int64_t first = 0, last = 0;
};
FrameRange parseFrames(const std::string& text);  // "A..B"; UsageError otherwise

// One frame's work, checked.
struct FrameJob {
    RenderSettings settings;
    AdaptiveSettings adaptive;
    double timeLimit = 0;  // seconds; 0: none
    double checkpointSeconds = 0;
    bool denoise = false;
    AovSet aovs;
    ToneMapSettings toneMap;
    ProgressMode progress = ProgressMode::Bar;
    bool quiet = false;
    std::string progressLabel = "render";
    std::string resumeArgument;  // what --resume takes to continue after an interrupt ("": the state file)
    // SIGINT/SIGTERM stop the render cleanly and keep what it has. Off across MPI ranks, where
    // mpirun's SIGTERM ends a failed job and must leave no partial output behind.
    bool stopOnSignals = true;
};

// The checkpoint file that goes with an output image: "<output>.state".
std::filesystem::path statePathFor(const std::filesystem::path& output);

// Registers every render flag on cmd.
void addRenderOptions(CLI::App& cmd, RenderArgs& args);

}  // namespace penumbra::app
