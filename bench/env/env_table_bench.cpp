// Environment sampling-table build time (alias table over texels), up to a 4096 x 2048 map.
// Run: bench_env_table (Release build); figures go to docs/PERFORMANCE.md with the machine.
#include <benchmark/benchmark.h>

#include <random>

#include "render/env_table.h"

namespace penumbra {
namespace {

EnvironmentMap noisyMap(int w, int h) {
    EnvironmentMap m{"bench", w, h, {}};
    m.radiance.resize(std::size_t(w) * std::size_t(h));
    std::mt19937 rng(1);
    std::exponential_distribution<float> e(1.0f);  // heavy-ish tail, like a real HDR sky
    for (Vec3& v : m.radiance) v = Vec3{e(rng), e(rng), e(rng)};
    return m;
}

void BM_BuildEnvTable(benchmark::State& state) {
    const int w = int(state.range(0));
    const EnvironmentMap map = noisyMap(w, w / 2);
    for (auto _ : state) benchmark::DoNotOptimize(buildEnvTable(map));
    state.SetItemsProcessed(state.iterations() * std::int64_t(map.radiance.size()));
}
BENCHMARK(BM_BuildEnvTable)->Arg(512)->Arg(2048)->Arg(4096)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace penumbra

BENCHMARK_MAIN();
