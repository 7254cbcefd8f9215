// Top-level rebuild of a two-level BVH: the world bounds of every instance (its bottom level's box
// through its transform) and the build over them (bvh::replaceTopLevel, into buffers kept from
// the last frame, as the renderer does it), what moving any instance costs.
// Run: bench_bvh_build --benchmark_filter=TopLevel (Release build). From 2,048 instances the
// rebuild runs on TBB's worker pool, so the figure to read is Time (wall), not CPU (the calling
// thread's alone); BM_TopLevelRebuildOneThread is the same rebuild on the calling thread.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "bvh/morton_build.h"
#include "bvh/stats.h"
#include "bvh/two_level.h"
#include "core/transform.h"

namespace penumbra::bvh {
namespace {

template <BuildThreads kThreads>
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
    const std::vector<Aabb> objectBounds(count, local);
    std::vector<shader::BvhNode> nodes(1000);  // stand-ins for the bottom levels
    TopLevelScratch scratch;
    for (auto _ : state) {
        replaceTopLevel(nodes, 1000, instances, objectBounds, scratch, kThreads);
        benchmark::DoNotOptimize(nodes.data());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(count));
}
BENCHMARK(BM_TopLevelRebuild<BuildThreads::Pool>)
    ->Name("BM_TopLevelRebuild")->Arg(1000)->Arg(10000)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TopLevelRebuild<BuildThreads::One>)
    ->Name("BM_TopLevelRebuildOneThread")->Arg(1000)->Arg(10000)->UseRealTime()->Unit(benchmark::kMillisecond);

// The two builders alone on the same boxes (the rebuild above picks one by count); the counter
// is the tree's SAH cost, one instance per leaf.
template <bool kMorton>
void BM_TopLevelBuilder(benchmark::State& state) {
    const auto count = std::size_t(state.range(0));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> where(-100.0f, 100.0f), size(0.5f, 2.0f);
    std::vector<Aabb> boxes(count);
    for (Aabb& b : boxes) {
        const Vec3 c{where(rng), where(rng) * 0.1f, where(rng)};
        b.grow(c - Vec3{size(rng)});
        b.grow(c + Vec3{size(rng)});
    }
    BuildOptions one;
    one.maxLeafSize = 1;
    Bvh tree;
    for (auto _ : state) {
        tree = kMorton ? buildMorton(boxes) : build(boxes, one);
        benchmark::DoNotOptimize(tree.nodes.data());
    }
    state.counters["sah_cost"] = computeStats(tree, one).sahCost;
}
BENCHMARK(BM_TopLevelBuilder<false>)->Name("BM_TopLevelBinnedSah")->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TopLevelBuilder<true>)->Name("BM_TopLevelMorton")->Arg(1000)->Arg(10000)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace penumbra::bvh
