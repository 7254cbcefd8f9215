// The one place the program reads its PENUMBRA_* environment variables (docs/ARCHITECTURE.md,
// "Environment variables", says which): once, at start, into the settings the modules are given.
// A malformed value is a UsageError naming the variable; an unset or empty one is the default.
#pragma once

#include <filesystem>

#include "render/tuning.h"

namespace penumbra::app {

// PENUMBRA_TRACE_KERNEL, PENUMBRA_WAVE_*, PENUMBRA_GENERIC_KERNEL, PENUMBRA_LIGHT_GRID*,
// PENUMBRA_FORCE_INSTANCES.
RenderTuning renderTuningFromEnvironment();

// PENUMBRA_CACHE_DIR, else $XDG_CACHE_HOME/penumbra, else $HOME/.cache/penumbra; empty when none
// is set (no cache).
std::filesystem::path bvhCacheDirectoryFromEnvironment();

// Reads the variables above and hands them to render/ (setRenderTuning); main() calls it once.
void applyEnvironmentSettings();

}  // namespace penumbra::app
