// Options several commands share (device choice, scene and camera overrides), and turning
// them into a scene and a GPU context.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <optional>
#include <string>

#include "gpu/context.h"
#include "render/settings.h"
#include "render/view_settings.h"
#include "scene/io/env_spec.h"
#include "scene/io/scene_json.h"
#include "scene/io/wad/wad_loader.h"
#include "scene/scene.h"

namespace penumbra::app {

struct CameraOverrides {
    std::string position, lookAt, up;  // "x,y,z" as typed
    std::optional<float> fov;
    std::optional<float> torch;  // candela; 0 turns the torch off
    std::string torchColor;      // "r,g,b" linear colour of the torch
    std::optional<float> torchRange;  // metres; 0: unlimited
    std::optional<float> aperture, focusDistance;  // thin lens, metres
    std::string focusPoint;                        // "x,y,z": focus at its depth along the view
};

// Help for a command's scene argument: every built-in scene and file format, from where they are
// registered (presets/registry.cpp, io/load.cpp).
std::string sceneArgumentHelp();

void addDeviceOption(CLI::App& cmd, std::string& device);
// --bvh-build cpu|gpu (render, view, bench, info): where the flat world's BVH is built, parsed
// into `where` as the command line is read (a bad name is a usage error).
void addBvhBuildOption(CLI::App& cmd, BvhBuild& where);
// --no-bvh-cache on a command; configureBvhCache() (main, before the action) reads it.
void addBvhCacheOption(CLI::App& cmd);
// Turns the on-disk BVH cache (bvh/cache.h) on in its default folder (PENUMBRA_CACHE_DIR,
// XDG_CACHE_HOME or ~/.cache, + /penumbra), unless --no-bvh-cache was given.
void configureBvhCache();
void addCameraOptions(CLI::App& cmd, CameraOverrides& overrides);
// --env FILE|sky, --env-intensity X, --env-rotation DEG.
void addEnvironmentOptions(CLI::App& cmd, EnvironmentSpec& env);
// --wad-glow SCALE, --wad-sector-light SCALE, --wad-filter nearest|bilinear (Doom levels).
void addWadOptions(CLI::App& cmd, WadOptions& wad);
// --no-phantom (view, serve, render): the dungeon's phantom starts switched off, as H leaves it
// (scene/phantom.h). On by default everywhere, so a render shows what the viewer shows.
void addPhantomOption(CLI::App& cmd, bool& phantom);
// The view settings both the window and the browser start from (view, serve): --resolution-scale
// and the other settings the WebGPU renderer offers; checked with checkViewSettingRanges.
void addViewSettingOptions(CLI::App& cmd, ViewSettings& view);

// Parses "x,y,z"; UsageError naming the flag on anything else.
Vec3 parseVec3(const std::string& text, const std::string& flag);

// A built-in scene by name or a scene file (`map` picks a WAD level), with the camera overrides
// applied and checked, the environment options applied, and the torch attached. A .json scene
// file's render settings go to *fileSettings when given.
Scene loadScene(const std::string& nameOrPath, const std::string& map, const CameraOverrides& overrides,
                SceneFileSettings* fileSettings = nullptr, const EnvironmentSpec& env = {}, const WadOptions& wad = {});

// The Vulkan context, or an Error saying why there is none and how to get one.
std::unique_ptr<gpu::Context> openDevice(const std::string& selector);

}  // namespace penumbra::app
