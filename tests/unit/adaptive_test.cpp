// Adaptive sampling on the host, with synthetic "GPU" rounds: the image stays unbiased when
// converged pixels skip rounds, flat pixels stop early, noisy ones keep sampling, and the plan
// is a pure function of the sums (so a resumed render decides the same).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "render/accumulator.h"
#include "render/adaptive.h"

namespace penumbra {
namespace {

// A W x H image whose left half is a flat grey (every sample 0.5) and whose right half is a
// coin: each sample is 1 with probability 1/2, else 0 (mean 0.5, relative error 1/sqrt(n)).
constexpr std::uint32_t kW = 64, kH = 32;
constexpr double kTrueMean = 0.5;

bool noisy(std::size_t pixel) { return pixel % kW >= kW / 2; }

// The GPU's buffer for one round: per pixel the sum of `samples` samples (grey) and the sum of
// their squared luminance; nothing for pixels the plan skips.
std::vector<Vec4> traceRound(const RoundPlan& plan, std::uint32_t samples, std::mt19937_64& rng) {
    std::vector<Vec4> sums(std::size_t(kW) * kH, Vec4{0, 0, 0, 0});
    std::bernoulli_distribution coin(0.5);
    for (std::size_t i = 0; i < sums.size(); ++i) {
        if (plan.adaptive && !plan.active[i]) continue;
        double sum = 0, squares = 0;
        for (std::uint32_t s = 0; s < samples; ++s) {
            const double x = noisy(i) ? (coin(rng) ? 1.0 : 0.0) : kTrueMean;
            sum += x;
            squares += x * x;
        }
        sums[i] = Vec4{float(sum), float(sum), float(sum), float(squares)};
    }
    return sums;
}

struct Result {
    PixelAccumulator sums;
    std::uint64_t samplesTraced = 0;
};

Result render(const AdaptiveSettings& adaptive, std::uint32_t rounds, std::uint32_t perRound, std::uint64_t seed) {
    Result r{PixelAccumulator(kW, kH, adaptive.enabled())};
    std::mt19937_64 rng(seed);
    for (std::uint32_t round = 0; round < rounds; ++round) {
        const RoundPlan plan = planRound(r.sums, adaptive, 7, round);
        r.sums.addRound(traceRound(plan, perRound, rng), perRound, plan);
    }
    for (std::size_t i = 0; i < r.sums.pixelCount(); ++i) r.samplesTraced += r.sums.samplesTaken(i);
    return r;
}

AdaptiveSettings adaptiveSettings(float threshold) {
    AdaptiveSettings s;
    s.threshold = threshold;
    s.tileSize = 1;  // every pixel decides for itself, so the noisy pixels are independent
    return s;
}

struct RegionStats {
    double mean = 0, stddev = 0;  // over the pixels of the noisy half
};

RegionStats noisyRegion(const ImageRgb& image) {
    std::vector<double> values;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        if (noisy(i)) values.push_back(image.pixels[i].x);
    RegionStats s;
    for (double v : values) s.mean += v;
    s.mean /= double(values.size());
    for (double v : values) s.stddev += (v - s.mean) * (v - s.mean);
    s.stddev = std::sqrt(s.stddev / double(values.size() - 1));
    return s;
}

TEST(AdaptiveSampling, WithoutAThresholdEveryPixelTakesEverySample) {
    const Result r = render(AdaptiveSettings{}, 4, 16, 1);
    EXPECT_EQ(r.sums.nominalSamples(), 64u);
    EXPECT_EQ(r.samplesTraced, 64u * kW * kH);
    EXPECT_FALSE(planRound(r.sums, AdaptiveSettings{}, 7, 4).adaptive);
}

TEST(AdaptiveSampling, ImageStaysUnbiasedWhileConvergedPixelsSkipRounds) {
    // Threshold 0.1: a coin pixel converges near 100 samples, then is sampled with probability
    // (e / t)^2 per round. Over 1024 independent pixels the mean of the estimates must match the
    // true mean within 4 standard errors of that mean (the spread measured across pixels).
    const Result r = render(adaptiveSettings(0.1f), 40, 16, 2);
    const RegionStats s = noisyRegion(r.sums.image());
    const double standardError = s.stddev / std::sqrt(double(kW / 2 * kH));
    EXPECT_NEAR(s.mean, kTrueMean, 4 * standardError) << "stddev " << s.stddev;
    // Samples were saved on the noisy half too (otherwise this test exercised nothing).
    double noisyTaken = 0;
    for (std::size_t i = 0; i < r.sums.pixelCount(); ++i)
        if (noisy(i)) noisyTaken += r.sums.samplesTaken(i);
    EXPECT_LT(noisyTaken, 0.7 * 640.0 * (kW / 2 * kH));
}

TEST(AdaptiveSampling, FinalErrorStaysNearTheThreshold) {
    // With p = (e / t)^2 each skipped round adds at most t^2 Y^2 / N of variance, so the
    // relative error across pixels ends within a small factor of the threshold (the fixed
    // 640-sample render would reach 1/sqrt(640) = 0.04).
    const float t = 0.1f;
    const Result r = render(adaptiveSettings(t), 40, 16, 3);
    const RegionStats s = noisyRegion(r.sums.image());
    EXPECT_LT(s.stddev / s.mean, 1.5 * t);
    EXPECT_GT(s.stddev / s.mean, 0.5 / std::sqrt(640.0));  // and it did not sample everything
}

TEST(AdaptiveSampling, FlatPixelsStopEarlyAndStayExact) {
    AdaptiveSettings a = adaptiveSettings(0.02f);
    const Result r = render(a, 40, 16, 4);
    const ImageRgb image = r.sums.image();
    double flatTaken = 0, noisyTaken = 0;
    for (std::size_t i = 0; i < r.sums.pixelCount(); ++i) {
        (noisy(i) ? noisyTaken : flatTaken) += r.sums.samplesTaken(i);
        // A zero-variance pixel's control mean is exact: skipping it adds no error at all.
        if (!noisy(i)) {
            EXPECT_NEAR(image.pixels[i].x, kTrueMean, 1e-6) << i;
        }
        EXPECT_GE(r.sums.samplesTaken(i), a.minSamples) << i;
    }
    const double half = double(kW / 2 * kH);
    // Flat pixels: the first minSamples, then each round with probability minProbability.
    EXPECT_LT(flatTaken / half, a.minSamples + 2.0 * a.minProbability * 640);
    // Noisy pixels at t = 0.02 would need 2500 samples: they sampled every round.
    EXPECT_EQ(noisyTaken / half, 640.0);
}

TEST(AdaptiveSampling, TilesDecideTogether) {
    AdaptiveSettings a = adaptiveSettings(0.1f);
    a.tileSize = 8;
    const Result r = render(a, 12, 16, 5);
    const RoundPlan plan = planRound(r.sums, a, 7, 12);
    for (std::uint32_t y = 0; y < kH; ++y)
        for (std::uint32_t x = 0; x < kW; ++x) {
            const std::size_t i = std::size_t(y) * kW + x, first = std::size_t(y / 8 * 8) * kW + x / 8 * 8;
            EXPECT_EQ(plan.active[i], plan.active[first]);
            EXPECT_EQ(plan.probability[i], plan.probability[first]);
        }
}

TEST(AdaptiveSampling, PlanIsAFunctionOfTheSumsSeedAndRound) {
    const AdaptiveSettings a = adaptiveSettings(0.1f);
    const Result r = render(a, 10, 16, 6);
    const RoundPlan p1 = planRound(r.sums, a, 7, 10), p2 = planRound(PixelAccumulator(r.sums.data()), a, 7, 10);
    EXPECT_EQ(p1.active, p2.active);
    EXPECT_EQ(p1.probability, p2.probability);
    // Another round throws other coins for the tiles that are not sampled for sure.
    const RoundPlan p3 = planRound(r.sums, a, 7, 11);
    EXPECT_NE(p1.active, p3.active);
}

TEST(AdaptiveSampling, RelativeErrorMatchesTheFormula) {
    PixelAccumulator sums(1, 1, true);
    RoundPlan plan;  // not adaptive: every pixel
    // Samples 0, 1, 0, 1: mean 0.5, sample variance 1/3, variance of the mean 1/12.
    sums.addRound(std::vector<Vec4>{Vec4{2, 2, 2, 2}}, 4, plan);
    EXPECT_NEAR(sums.meanLuminanceVariance(0), 1.0 / 12.0, 1e-9);
    EXPECT_NEAR(relativeError(sums, 0, 0.0), std::sqrt(1.0 / 12.0) / 0.5, 1e-6);
    // Below the floor, the floor is the scale.
    EXPECT_NEAR(relativeError(sums, 0, 2.0), std::sqrt(1.0 / 12.0) / 2.0, 1e-6);
}

}  // namespace
}  // namespace penumbra
