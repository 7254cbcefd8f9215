// Which optional parts of the tracing kernels a scene needs (PN_FEATURE_* in shared/types.h):
// pipelines are specialised with it, so a Doom level's kernel carries no sphere, glass or
// environment-map code. PENUMBRA_GENERIC_KERNEL=1 keeps every part (the A/B baseline).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "render/gpu_scene.h"
#include "render/settings.h"

namespace penumbra {

// Scenes with at least this many lights get the shadow-ray roulette (PN_FEATURE_SHADOW_ROULETTE).
// It pays where one light sample among many often carries little: on the H200 (session 33) the
// Doom maps' frames (294 and 676 lights) were 7-17% faster with it, while the scenes of 2-4 lights
// traced 1-3% fewer rays and were up to 2% slower, paying for the test on every light sample.
constexpr std::size_t kShadowRouletteMinLights = 16;

// cullBackfaces adds PN_FEATURE_CULL_BACKFACES (--cull-backfaces), generic kernels included.
std::uint32_t kernelFeatures(const SceneArrays& arrays, Accel accel, bool cullBackfaces = false);

// Names of the features set in `features`, comma-separated ("spheres,textures"), for reports.
std::string kernelFeatureNames(std::uint32_t features);

}  // namespace penumbra
