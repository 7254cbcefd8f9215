// The CPU cost of a moving Doom level per tic (issue 40's target: at most 0.1 ms): the level's
// tic (every mover steps), the moving planes' instances moved (interact/doom_play.h), and the top
// level of the two-level BVH rebuilt as InteractiveRenderer::setInstanceTransforms does. Every
// door, lift and crusher of Freedoom's E1M1 (or DOOM1_WAD's) is set moving first, so each tic
// moves them all: a worst case the walks never reach. Run: bench_doom_level (Release build).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "bvh/two_level.h"
#include "interact/doom_play.h"
#include "render/gpu_scene.h"
#include "render/instance_arrays.h"
#include "scene/doom/level.h"
#include "scene/io/wad/wad_loader.h"

namespace penumbra {
namespace {

std::string wadPath() {
    const char* doom1 = std::getenv("DOOM1_WAD");
    return doom1 && *doom1 ? doom1 : "/usr/share/games/doom/freedoom1.wad";
}

void BM_DoomLevelTic(benchmark::State& state) {
    if (!std::filesystem::exists(wadPath())) {
        state.SkipWithError((wadPath() + " is missing").c_str());
        return;
    }
    Scene scene = loadWad(wadPath(), "E1M1");
    const doom::Level started = doom::withEverythingMoving(*scene.doomLevel);
    doom::Level level = started;
    SceneArrays arrays = buildSceneArrays(scene);
    viewer::CameraController controller(scene.camera, 1.0f, scene.walkMap);
    std::size_t moved = 0;
    for (auto _ : state) {
        if (level.activeMovers() == 0) {  // all arrived: start them again (not timed)
            state.PauseTiming();
            level = started;
            state.ResumeTiming();
        }
        level.tic(std::nullopt);
        doom::placePlaneInstances(level, scene.instances);
        controller.setSectorHeights(level.walkMap().sectors);
        for (shader::Instance& i : arrays.instances) {
            if (i.id == PN_NO_HIT || i.id >= scene.instances.size()) continue;
            i = bvh::makeInstance(scene.instances[i.id].transform, i.rootNode, i.firstPrimitive, i.primitiveCount, i.id);
        }
        rebuildTopLevel(arrays);
        benchmark::DoNotOptimize(arrays.nodes.data());
        moved = std::max(moved, level.activeMovers());
    }
    state.counters["instances"] = double(arrays.instances.size());
    state.counters["movers"] = double(moved);
}
BENCHMARK(BM_DoomLevelTic)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace penumbra

BENCHMARK_MAIN();
