// The CPU cost of a moving Doom level per tic (issue 40's target: at most 0.1 ms), as the viewer
// pays it (interact/play_step.cpp): the level's tic (every mover and light special steps, the
// walking's heights follow), the moving planes' instances moved, the sector lights' materials
// set, and the instances' records and the top level of the two-level BVH rebuilt on the host
// (render/instance_arrays.h moveInstances, what InteractiveRenderer::setInstanceTransforms and
// Renderer::setInstanceTransforms run). The upload to the GPU is not timed. Every door, lift and
// crusher of Freedoom's E1M1 (or DOOM1_WAD's) is set moving first, so each tic moves them all: a
// worst case the walks never reach. Run: bench_doom_level (Release build).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

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
    viewer::DoomPlay play(started);
    SceneArrays arrays = buildSceneArrays(scene);
    viewer::CameraController controller(scene.camera, 1.0f, scene.walkMap);
    std::size_t moved = 0;
    for (auto _ : state) {
        if (play.level().activeMovers() == 0) {  // all arrived: start them again (not timed)
            state.PauseTiming();
            play = viewer::DoomPlay(started);
            state.ResumeTiming();
        }
        play.update(controller, std::nullopt, 1.0f / doom::kTicsPerSecond);  // one tic
        play.moveSectors(scene);
        benchmark::DoNotOptimize(play.applyLights(scene));
        moveInstances(arrays, scene);
        benchmark::DoNotOptimize(arrays.nodes.data());
        moved = std::max(moved, play.level().activeMovers());
    }
    state.counters["instances"] = double(arrays.instances.size());
    state.counters["movers"] = double(moved);
}
BENCHMARK(BM_DoomLevelTic)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace penumbra

BENCHMARK_MAIN();
