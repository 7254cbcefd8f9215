#include "render/adaptive.h"

#include <algorithm>
#include <cmath>

#include "core/parallel.h"

namespace penumbra {
namespace {

// A uniform number in [0, 1) from (seed, round, tile): splitmix64's finaliser over their mix.
double coin(std::uint32_t seed, std::uint64_t round, std::uint64_t tile) {
    std::uint64_t z = (std::uint64_t(seed) << 32) ^ (round * 0x9E3779B97F4A7C15ull) ^ (tile * 0xD1B54A32D192ED03ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return double(z >> 11) * 0x1.0p-53;
}

}  // namespace

double errorFloor(const PixelAccumulator& sums) {
    const auto& d = sums.data();
    if (d.nominalSamples == 0 || sums.pixelCount() == 0) return 0;
    double total = 0;
    for (std::size_t i = 0; i < sums.pixelCount(); ++i)
        total += double(luminance(Vec3{float(d.estimate[3 * i]), float(d.estimate[3 * i + 1]), float(d.estimate[3 * i + 2])}));
    return kErrorFloorFraction * total / (double(d.nominalSamples) * double(sums.pixelCount()));
}

float relativeError(const PixelAccumulator& sums, std::size_t pixel, double floorLuminance) {
    const double y = luminance(sums.rawMean(pixel));
    const double scale = std::max({y, floorLuminance, 1e-12});
    return float(std::sqrt(sums.meanLuminanceVariance(pixel)) / scale);
}

RoundPlan planRound(const PixelAccumulator& sums, const AdaptiveSettings& s, std::uint32_t seed, std::uint64_t round) {
    RoundPlan plan;
    plan.adaptive = s.enabled();
    if (!plan.adaptive) return plan;
    const std::uint32_t w = sums.width(), h = sums.height(), tile = std::max(1u, s.tileSize);
    const std::size_t n = sums.pixelCount();
    plan.probability.assign(n, 1.0f);
    plan.active.assign(n, 1u);
    plan.control.assign(n, Vec3{0.0f});
    const double floorY = errorFloor(sums);
    const std::uint32_t tilesX = (w + tile - 1) / tile, tilesY = (h + tile - 1) / tile;
    parallelFor(std::size_t(tilesX) * tilesY, 16, [&](std::size_t begin, std::size_t end) {
        for (std::size_t t = begin; t < end; ++t) {
            const std::uint32_t x0 = std::uint32_t(t % tilesX) * tile, y0 = std::uint32_t(t / tilesX) * tile;
            const std::uint32_t x1 = std::min(w, x0 + tile), y1 = std::min(h, y0 + tile);
            float p = s.minProbability;
            for (std::uint32_t y = y0; y < y1 && p < 1.0f; ++y)
                for (std::uint32_t x = x0; x < x1 && p < 1.0f; ++x) {
                    const std::size_t i = std::size_t(y) * w + x;
                    if (sums.samplesTaken(i) < s.minSamples) {
                        p = 1.0f;
                        break;
                    }
                    const float e = relativeError(sums, i, floorY);
                    p = std::max(p, e >= s.threshold ? 1.0f : (e / s.threshold) * (e / s.threshold));
                }
            p = std::clamp(p, s.minProbability, 1.0f);
            const std::uint32_t active = p >= 1.0f || coin(seed, round, t) < p ? 1u : 0u;
            for (std::uint32_t y = y0; y < y1; ++y)
                for (std::uint32_t x = x0; x < x1; ++x) {
                    const std::size_t i = std::size_t(y) * w + x;
                    plan.probability[i] = p;
                    plan.active[i] = active;
                    plan.control[i] = sums.rawMean(i);
                }
        }
    });
    return plan;
}

}  // namespace penumbra
