// Adaptive sampling (--noise-threshold): which pixels take the next round of samples.
//
// Estimator (docs/RENDERING.md, "Adaptive sampling"): after n samples a pixel's relative error
// is e = sqrt(s^2 / n) / max(Y, floor), with Y the luminance of its mean, s^2 the unbiased
// sample variance of its samples' luminance, and floor = kErrorFloorFraction of the image's
// mean luminance (so near-black pixels are judged against what the eye sees, not against 0).
// A pixel with e >= threshold, or fewer than minSamples samples, is sampled for sure; a pixel
// below the threshold has converged and is sampled with probability p = max(pMin, (e / t)^2).
// The sampled pixels' samples are weighted as RoundPlan says, so the image stays unbiased, and
// with p = (e / t)^2 every later sample adds at most t^2 Y^2 / N to the pixel's variance: the
// relative error at the end stays near the threshold. Decisions are made per tile (the largest
// p of its pixels), so the GPU skips whole workgroups; the coin of a tile comes from a hash of
// (seed, round, tile), so a resumed render makes the same decisions.
#pragma once

#include <cstdint>

#include "render/accumulator.h"

namespace penumbra {

constexpr float kErrorFloorFraction = 0.01f;

struct AdaptiveSettings {
    float threshold = 0;            // relative error; 0: adaptive sampling off
    std::uint32_t minSamples = 32;  // no pixel converges before it has this many samples
    std::uint32_t tileSize = 8;     // pixels per side of a decision tile (the trace workgroup)
    float minProbability = 1.0f / 32.0f;  // a converged tile is still sampled this often (> 0: unbiased)

    bool enabled() const { return threshold > 0; }
};

// The plan for round `round` from the sums so far. Without adaptivity: every pixel, p = 1.
RoundPlan planRound(const PixelAccumulator& sums, const AdaptiveSettings& settings, std::uint32_t seed,
                    std::uint64_t round);

// The relative error of each pixel (the estimator above), for tests and the variance AOV's users.
float relativeError(const PixelAccumulator& sums, std::size_t pixel, double floorLuminance);

// kErrorFloorFraction of the mean luminance of the image so far.
double errorFloor(const PixelAccumulator& sums);

}  // namespace penumbra
