// BVH build time on random soups, the wide collapse, and CPU reference closest-hit throughput.
// Run: bench_bvh_build (Release build); figures go to docs/PERFORMANCE.md with the machine.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "bvh/builder.h"
#include "bvh/stats.h"
#include "bvh/traverse_cpu.h"
#include "bvh/wide.h"
#include "core/parallel.h"
#include "scene/io/load.h"

namespace penumbra::bvh {
namespace {

// The same kind of soup the tests use: triangles around random centres in the unit cube,
// shrinking with the count so the density resembles a mesh.
std::vector<Triangle> soup(std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f), u11(-1.0f, 1.0f);
    float size = 0.5f / std::cbrt(float(count));
    std::vector<Triangle> tris(count);
    for (auto& t : tris) {
        Vec3 c(u01(rng), u01(rng), u01(rng));
        t.v0 = c + Vec3(u11(rng), u11(rng), u11(rng)) * size;
        t.v1 = c + Vec3(u11(rng), u11(rng), u11(rng)) * size;
        t.v2 = c + Vec3(u11(rng), u11(rng), u11(rng)) * size;
    }
    return tris;
}

void BM_BuildRandomSoup(benchmark::State& state) {
    auto tris = soup(std::size_t(state.range(0)), 1);
    BuildOptions options;
    Bvh bvh;
    for (auto _ : state) {
        bvh = buildTriangles(tris, options);
        benchmark::DoNotOptimize(bvh.nodes.data());
    }
    BvhStats s = computeStats(bvh, options);
    state.counters["tris/s"] =
        benchmark::Counter(double(tris.size()), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["sah"] = s.sahCost;
    state.counters["depth"] = double(s.maxDepth);
    state.counters["threads"] = hardwareThreads();
}
BENCHMARK(BM_BuildRandomSoup)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// A real mesh: any scene file the loaders read (the Stanford bunny by default; point
// PENUMBRA_BENCH_MESH at a bigger one, e.g. the dragon PLY). Skipped when the file is missing.
void BM_BuildMesh(benchmark::State& state) {
    const char* env = std::getenv("PENUMBRA_BENCH_MESH");
    const std::string path = env ? env : "/usr/share/glmark2/models/bunny.obj";
    std::vector<Triangle> tris;
    try {
        tris = trianglesOf(flattenTriangles(loadSceneFile(path)));
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
        return;
    }
    BuildOptions options;
    Bvh bvh;
    for (auto _ : state) {
        bvh = buildTriangles(tris, options);
        benchmark::DoNotOptimize(bvh.nodes.data());
    }
    BvhStats s = computeStats(bvh, options);
    state.SetLabel(std::filesystem::path(path).filename().string());
    state.counters["tris"] = double(tris.size());
    state.counters["tris/s"] =
        benchmark::Counter(double(tris.size()), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["sah"] = s.sahCost;
    state.counters["threads"] = hardwareThreads();
}
BENCHMARK(BM_BuildMesh)->Unit(benchmark::kMillisecond)->UseRealTime();

// Collapsing the binary tree of a 1M-triangle soup (range 0) or of PENUMBRA_BENCH_MESH (range 0 =
// 0, the bunny by default) into the wide BVH; range 1 is CollapseOptions::taskPrimitives (0: one
// thread). The copy of the binary tree that each collapse reorders is not timed.
void BM_CollapseWide(benchmark::State& state) {
    std::vector<Triangle> tris;
    if (state.range(0) > 0) {
        tris = soup(std::size_t(state.range(0)), 1);
    } else {
        const char* env = std::getenv("PENUMBRA_BENCH_MESH");
        try {
            tris = trianglesOf(flattenTriangles(loadSceneFile(env ? env : "/usr/share/glmark2/models/bunny.obj")));
        } catch (const std::exception& e) {
            state.SkipWithError(e.what());
            return;
        }
    }
    const Bvh tree = buildTriangles(tris);
    const CollapseOptions options{std::uint32_t(state.range(1))};
    std::size_t wideNodes = 0;
    for (auto _ : state) {
        state.PauseTiming();
        Bvh copy = tree;
        state.ResumeTiming();
        wideNodes = collapseToWide(copy, options).nodes.size();
        benchmark::DoNotOptimize(wideNodes);
    }
    state.counters["tris"] = double(tris.size());
    state.counters["wide nodes"] = double(wideNodes);
    state.counters["threads"] = options.taskPrimitives ? hardwareThreads() : 1;
}
BENCHMARK(BM_CollapseWide)
    ->Args({1'000'000, 0})
    ->Args({1'000'000, CollapseOptions{}.taskPrimitives})
    ->Args({0, 0})
    ->Args({0, CollapseOptions{}.taskPrimitives})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// One thread, primary-like rays from outside the cube at random points inside it.
void BM_ClosestHitCpu(benchmark::State& state) {
    auto tris = soup(std::size_t(state.range(0)), 2);
    Bvh bvh = buildTriangles(tris);
    auto leafTris = leafOrderTriVerts(bvh, tris);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Ray> rays(4096);
    for (auto& r : rays) {
        r.origin = Vec3(u(rng) * 3 - 1, u(rng) * 3 - 1, -1.0f);
        r.direction = Vec3(u(rng), u(rng), u(rng)) - r.origin;
    }
    std::size_t hits = 0;
    for (auto _ : state)
        for (const Ray& r : rays) hits += closestHit(bvh.nodes, leafTris, r).triangle != PN_NO_HIT;
    benchmark::DoNotOptimize(hits);
    state.counters["rays/s"] =
        benchmark::Counter(double(rays.size()), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["hit%"] = 100.0 * double(hits) / double(rays.size() * state.iterations());
}
BENCHMARK(BM_ClosestHitCpu)->Arg(100'000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace penumbra::bvh

BENCHMARK_MAIN();
