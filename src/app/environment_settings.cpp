#include "app/environment_settings.h"

#include <cstdlib>
#include <string>
#include <string_view>

#include "core/environment.h"
#include "core/error.h"

namespace penumbra::app {
namespace {

std::string_view text(const char* name) {
    const char* value = std::getenv(name);
    return value ? std::string_view(value) : std::string_view();
}

TraceKernel traceKernel() {
    const std::string_view name = text("PENUMBRA_TRACE_KERNEL");
    if (name.empty() || name == "auto") return TraceKernel::Auto;
    if (name == "mega") return TraceKernel::Megakernel;
    if (name == "wavefront") return TraceKernel::Wavefront;
    throw UsageError("PENUMBRA_TRACE_KERNEL must be 'auto', 'mega' or 'wavefront' (got '" +
                     std::string(name) + "')");
}

}  // namespace

RenderTuning renderTuningFromEnvironment() {
    RenderTuning t;
    t.traceKernel = traceKernel();
    t.waveTailPaths = std::uint32_t(
        environmentSetting("PENUMBRA_WAVE_TAIL_PATHS", t.waveTailPaths, 0, UINT32_MAX));
    // Switches as they always were read: exactly "1" for these two, anything but "0" for generic.
    t.waveStageTimes = text("PENUMBRA_WAVE_STAGE_TIMES") == "1";
    t.forceInstances = text("PENUMBRA_FORCE_INSTANCES") == "1";
    const std::string_view generic = text("PENUMBRA_GENERIC_KERNEL");
    t.genericKernel = !generic.empty() && generic != "0";
    t.lightGrid = environmentSetting("PENUMBRA_LIGHT_GRID", 1, 0, 1) != 0;
    t.restTree = environmentSetting("PENUMBRA_REST_TREE", 1, 0, 1) != 0;
    LightGridOptions& grid = t.lightGridOptions;
    grid.drawInClusters = environmentSetting("PENUMBRA_LIGHT_GRID_DRAW", 1, 0, 1) != 0;
    grid.levels = std::uint32_t(
        environmentSetting("PENUMBRA_LIGHT_GRID_LEVELS", grid.levels, 1, PN_LIGHT_GRID_MAX_LEVELS));
    grid.maxWords = environmentSetting("PENUMBRA_LIGHT_GRID_MB", grid.maxWords * 4 >> 20, 1, 1024)
                    << 18;  // 2^18 words a MiB
    return t;
}

std::filesystem::path bvhCacheDirectoryFromEnvironment() {
    if (const std::string_view dir = text("PENUMBRA_CACHE_DIR"); !dir.empty()) return dir;
    if (const std::string_view xdg = text("XDG_CACHE_HOME"); !xdg.empty())
        return std::filesystem::path(xdg) / "penumbra";
    if (const std::string_view home = text("HOME"); !home.empty())
        return std::filesystem::path(home) / ".cache" / "penumbra";
    return {};
}

void applyEnvironmentSettings() { setRenderTuning(renderTuningFromEnvironment()); }

}  // namespace penumbra::app
