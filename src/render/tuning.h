// The renderer's measurement switches (A/B) and test hooks: one struct, set once per process.
// app/ fills it from the PENUMBRA_* environment variables at start (app/environment_settings.h);
// tests set it directly. Its defaults are the shipped behaviour, so a program or test that never
// sets it renders as a user's default run does. docs/ARCHITECTURE.md, "Environment variables".
#pragma once

#include <cstdint>

#include "render/light_grid.h"

namespace penumbra {

// Auto: the wavefront for passes of at least kWavefrontMinPaths paths, where it is faster on the
// H200 (1.9x on DOOM1 at 1280x800 x 4 spp, 1.3x at 960x540, even on Cornell), the megakernel
// below, where the wavefront's fixed cost per bounce (a dozen dispatches and barriers) outweighs
// what it saves (480x270: 25% slower on DOOM1). docs/PERFORMANCE.md has the crossover runs.
enum class TraceKernel { Auto, Megakernel, Wavefront };

// The live paths at or below which the wavefront's tail kernel follows them to their end instead
// of another round of the bounce loop (PassPush.waveTailPaths). Measured on an H200
// (docs/PERFORMANCE.md, session 27).
constexpr std::uint32_t kDefaultWaveTailPaths = 16384;

struct RenderTuning {
    TraceKernel traceKernel = TraceKernel::Auto;          // PENUMBRA_TRACE_KERNEL
    std::uint32_t waveTailPaths = kDefaultWaveTailPaths;  // PENUMBRA_WAVE_TAIL_PATHS; 0: never
    // PENUMBRA_WAVE_STAGE_TIMES: time each wavefront step (adds barriers).
    bool waveStageTimes = false;
    // PENUMBRA_GENERIC_KERNEL: kernels with every feature (PN_FEATURE_ALL).
    bool genericKernel = false;
    bool lightGrid = true;              // PENUMBRA_LIGHT_GRID=0: no grid, the plain light-tree walk
    LightGridOptions lightGridOptions;  // PENUMBRA_LIGHT_GRID_LEVELS, _MB, _DRAW
    bool forceInstances = false;  // PENUMBRA_FORCE_INSTANCES: the world's meshes as one instance
    // PENUMBRA_REST_TREE=0: a two-level scene at rest walks its two levels (render/rest_tree.h).
    bool restTree = true;
};

// The process's tuning (the defaults until set). Set it before renderers are made: each reads it
// when it builds its scene arrays and kernels.
const RenderTuning& renderTuning();
void setRenderTuning(const RenderTuning& tuning);

}  // namespace penumbra
