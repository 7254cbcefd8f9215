// Options several commands share (device choice, scene and camera overrides), and turning
// them into a scene and a GPU context.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <optional>
#include <string>

#include "gpu/context.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace penumbra::app {

struct CameraOverrides {
    std::string position, lookAt, up;  // "x,y,z" as typed
    std::optional<float> fov;
};

void addDeviceOption(CLI::App& cmd, std::string& device);
void addCameraOptions(CLI::App& cmd, CameraOverrides& overrides);

// Parses "x,y,z"; UsageError naming the flag on anything else.
Vec3 parseVec3(const std::string& text, const std::string& flag);

// A built-in scene by name, with the camera overrides applied and checked.
Scene loadScene(const std::string& name, const CameraOverrides& overrides);

// The Vulkan context, or an Error saying why there is none and how to get one.
std::unique_ptr<gpu::Context> openDevice(const std::string& selector);

}  // namespace penumbra::app
