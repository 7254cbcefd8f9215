// The final render's per-pixel sums, on the host in double precision. The GPU adds one round
// of passes (at most a few dozen samples a pixel) into its fp32 buffer; the round's sums are
// read back and added here, so a 64k-sample pixel loses nothing to fp32 rounding, and adaptive
// sampling (render/adaptive.h) gets its per-pixel statistics.
//
// The image is an unbiased estimate even when pixels skip rounds: see RoundPlan and
// docs/RENDERING.md, "Adaptive sampling".
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/vec.h"
#include "image/image.h"

namespace penumbra {

// How a round samples the image. Without adaptive sampling every pixel takes every sample.
// With it, pixel i takes the round's samples with probability probability[i] (active[i] is the
// coin already thrown), and its contribution for each of the round's n nominal samples is the
// control-variate estimator
//     c = m + (taken / p) * (x - m)
// with m = control[i], the pixel's mean so far. Given the past, E[c] = E[x] for any p > 0 and
// any m fixed before the round: skipping keeps the estimate unbiased, and a skipped converged
// pixel contributes its mean, not zero, so it does not turn noisy.
struct RoundPlan {
    bool adaptive = false;
    std::vector<float> probability;     // per pixel, in (0, 1]
    std::vector<std::uint32_t> active;  // per pixel: 1 if sampled this round (the GPU's mask)
    std::vector<Vec3> control;          // per pixel: the control mean m
};

// Everything the sums hold, for checkpoints (render/checkpoint.h).
struct AccumulatorData {
    std::uint32_t width = 0, height = 0;
    bool adaptive = false;
    std::uint64_t nominalSamples = 0;  // per pixel: the image is estimate / nominalSamples
    std::vector<double> estimate;      // 3 per pixel: sum of contributions (the raw sums without adaptivity)
    std::vector<double> squares;       // per pixel: sum of squared luminance of the samples taken
    std::vector<double> raw;           // adaptive only: 3 per pixel, sum of the samples taken
    std::vector<std::uint32_t> count;  // adaptive only: samples taken per pixel
};

class PixelAccumulator {
public:
    PixelAccumulator(std::uint32_t width, std::uint32_t height, bool adaptive);
    explicit PixelAccumulator(AccumulatorData data);  // checks the sizes (PN_CHECK)

    // Adds a round of `samples` nominal samples per pixel. sums: the GPU's buffer, rgb = sum of
    // radiance, a = sum of squared luminance, over the samples each pixel took.
    void addRound(std::span<const Vec4> sums, std::uint32_t samples, const RoundPlan& plan);

    // The mean radiance per pixel.
    ImageRgb image() const;

    // Samples each pixel took (the nominal count without adaptivity).
    std::uint32_t samplesTaken(std::size_t pixel) const;
    // Mean of the samples a pixel took, and the variance of that mean's luminance (s^2 / n,
    // s^2 the unbiased sample variance); 0 with fewer than two samples.
    Vec3 rawMean(std::size_t pixel) const;
    double meanLuminanceVariance(std::size_t pixel) const;

    std::uint32_t width() const { return d_.width; }
    std::uint32_t height() const { return d_.height; }
    std::size_t pixelCount() const { return std::size_t(d_.width) * d_.height; }
    std::uint64_t nominalSamples() const { return d_.nominalSamples; }
    const AccumulatorData& data() const { return d_; }

private:
    Vec3 contribution(std::size_t i, Vec4 sums, std::uint32_t samples, const RoundPlan* plan) const;

    AccumulatorData d_;
};

}  // namespace penumbra
