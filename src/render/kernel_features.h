// Which optional parts of the tracing kernels a scene needs (PN_FEATURE_* in shared/types.h):
// pipelines are specialised with it, so a Doom level's kernel carries no sphere, glass or
// environment-map code. PENUMBRA_GENERIC_KERNEL=1 keeps every part (the A/B baseline).
#pragma once

#include <cstdint>
#include <string>

#include "render/gpu_scene.h"
#include "render/settings.h"

namespace penumbra {

std::uint32_t kernelFeatures(const SceneArrays& arrays, Accel accel);

// Names of the features set in `features`, comma-separated ("spheres,textures"), for reports.
std::string kernelFeatureNames(std::uint32_t features);

}  // namespace penumbra
