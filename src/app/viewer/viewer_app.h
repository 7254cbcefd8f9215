// `penumbra view`: the window, its input and the frame loop.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "interact/input_script.h"
#include "render/settings.h"
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
    bool antiAliasing = true;  // view --no-jitter turns it off
    bool cullBackfaces = false;  // view --cull-backfaces
    BvhBuild bvhBuild = BvhBuild::Cpu;  // view --bvh-build: the scene's tree at open and reopen
    bool preview = false;        // view --preview: the fast preview while moving (V toggles it)
    DebugView debug = DebugView::None;
    // Scripted input (--script): played from the first frame, which then starts playing.
    std::optional<std::vector<ScriptEvent>> script;
    std::optional<double> fixedDt;  // seconds each frame advances time by, instead of the clock
    // Automation (--steps-per-frame): each drawn frame plays this many --fixed-dt steps, the script's
    // events and the world exactly as that many frames would, so a long walk draws fewer frames.
    std::uint32_t stepsPerFrame = 1;
    bool printCamera = false;       // print the final camera on exit
    bool fly = false;               // start in free flight on levels one can walk
    bool phantom = true;            // view --no-phantom: the dungeon's phantom starts switched off (H)
    ViewSettings view;              // the settings the flags set (addViewSettingOptions)
};

// "normals", "albedo", "depth", "motion", "samples", "nodes", "triangles" or "none"; UsageError otherwise.
DebugView parseDebugView(const std::string& name);

void runViewer(Scene scene, const ViewerOptions& options);

// `camera X,Y,Z direction DX,DY,DZ`: the line --print-camera writes.
std::string cameraLine(const Camera& camera);

}  // namespace penumbra::viewer
