// Refuses a scene the device cannot hold, before any of it is allocated: every scene buffer
// against maxStorageBufferRange, and their total against the device-local memory (gpu/limits.h).
#pragma once

#include <cstdint>
#include <vector>

#include "gpu/context.h"
#include "render/gpu_scene.h"

namespace penumbra {

struct SceneBufferSize {
    const char* name;  // what the user would call it: "triangles", "textures", ...
    std::uint64_t bytes;
};

// One entry per buffer GpuScene uploads; the sizes add up to deviceBytes(arrays).
std::vector<SceneBufferSize> sceneBufferSizes(const SceneArrays& arrays);

// Throws an Error naming the scene's size, the device's limit and what to do.
void checkSceneFitsDevice(const gpu::Context& ctx, const SceneArrays& arrays);

}  // namespace penumbra
