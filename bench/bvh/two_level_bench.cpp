// Top-level rebuild of a two-level BVH: the world bounds of every instance (its bottom level's box
// through its transform) and a binned-SAH build over them, what moving any instance costs.
// Run: bench_bvh_build --benchmark_filter=TopLevel (Release build).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "bvh/two_level.h"
#include "core/transform.h"

namespace penumbra::bvh {
namespace {

void BM_TopLevelRebuild(benchmark::State& state) {
    const auto count = std::size_t(state.range(0));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> where(-100.0f, 100.0f), angle(0.0f, 360.0f), size(0.5f, 2.0f);
    Aabb local;
    local.grow(Vec3{-1.0f, 0.0f, -0.8f});
    local.grow(Vec3{1.0f, 1.5f, 0.8f});
    std::vector<shader::Instance> instances;
    for (std::size_t i = 0; i < count; ++i) {
        const Affine t = Affine::translation({where(rng), where(rng) * 0.1f, where(rng)}) *
                         Affine::eulerDegrees({0, angle(rng), 0}) * Affine::scaling(Vec3{size(rng)});
        instances.push_back(makeInstance(t, 0, 0, 1, std::uint32_t(i)));
    }
    std::vector<Aabb> world(count);
    for (auto _ : state) {
        for (std::size_t i = 0; i < count; ++i) world[i] = transformBounds(local, objectToWorld(instances[i]));
        std::vector<shader::BvhNode> top = buildTopLevel(world, 1000);
        benchmark::DoNotOptimize(top.data());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(count));
}
BENCHMARK(BM_TopLevelRebuild)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace penumbra::bvh
