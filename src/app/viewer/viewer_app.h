// `penumbra view`: the window, its input and the frame loop.
#pragma once

#include <optional>
#include <string>

#include "render/view_settings.h"
#include "scene/scene.h"

namespace penumbra::viewer {

struct ViewerOptions {
    std::string device;
    int width = 1280, height = 720;
    bool vsync = true;
    // Automation (tests, scripted captures): start playing, render this many frames, write the
    // screenshot (if a path is given) and exit.
    std::optional<std::uint32_t> frames;
    std::string screenshot;
    std::uint32_t samplesPerFrame = 1;
    bool denoise = false;
    DebugView debug = DebugView::None;
};

// "normals", "albedo", "depth", "motion", "samples", "nodes", "triangles" or "none"; UsageError otherwise.
DebugView parseDebugView(const std::string& name);

void runViewer(Scene scene, const ViewerOptions& options);

}  // namespace penumbra::viewer
