#include "render/accumulator.h"

#include <algorithm>
#include <utility>

#include "core/error.h"
#include "core/parallel.h"

namespace penumbra {
namespace {

constexpr std::size_t kChunk = 4096;

// Luminance of a double-precision sum, with core/vec.h's weights (one formula, one place).
double luminanceOf(const double* rgb) {
    constexpr double r = luminance(Vec3{1, 0, 0}), g = luminance(Vec3{0, 1, 0}), b = luminance(Vec3{0, 0, 1});
    return r * rgb[0] + g * rgb[1] + b * rgb[2];
}

}  // namespace

PixelAccumulator::PixelAccumulator(std::uint32_t width, std::uint32_t height, bool adaptive) {
    d_.width = width;
    d_.height = height;
    d_.adaptive = adaptive;
    const std::size_t n = pixelCount();
    d_.estimate.assign(3 * n, 0.0);
    d_.squares.assign(n, 0.0);
    if (adaptive) {
        d_.raw.assign(3 * n, 0.0);
        d_.count.assign(n, 0);
    }
}

PixelAccumulator::PixelAccumulator(AccumulatorData data) : d_(std::move(data)) {
    const std::size_t n = pixelCount();
    PN_CHECK(d_.estimate.size() == 3 * n && d_.squares.size() == n);
    PN_CHECK(d_.adaptive ? d_.raw.size() == 3 * n && d_.count.size() == n : d_.raw.empty() && d_.count.empty());
}

Vec3 PixelAccumulator::contribution(std::size_t i, Vec4 s, std::uint32_t samples, const RoundPlan* plan) const {
    const Vec3 sum{s.x, s.y, s.z};
    if (!plan || !plan->adaptive || plan->probability[i] >= 1.0f) return sum;  // exact: no control term
    const Vec3 base = plan->control[i] * float(samples);
    if (!plan->active[i]) return base;
    return base + (sum - base) / plan->probability[i];
}

void PixelAccumulator::addRound(std::span<const Vec4> sums, std::uint32_t samples, const RoundPlan& plan) {
    PN_CHECK(sums.size() == pixelCount());
    PN_CHECK(!plan.adaptive || (d_.adaptive && plan.probability.size() == pixelCount()));
    parallelFor(pixelCount(), kChunk, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const Vec4 s = sums[i];
            const Vec3 c = contribution(i, s, samples, &plan);
            d_.estimate[3 * i] += c.x;
            d_.estimate[3 * i + 1] += c.y;
            d_.estimate[3 * i + 2] += c.z;
            d_.squares[i] += s.w;
            if (!d_.adaptive) continue;
            const bool taken = !plan.adaptive || plan.active[i];
            if (!taken) continue;
            d_.raw[3 * i] += s.x;
            d_.raw[3 * i + 1] += s.y;
            d_.raw[3 * i + 2] += s.z;
            d_.count[i] += samples;
        }
    });
    d_.nominalSamples += samples;
}

ImageRgb PixelAccumulator::image() const {
    ImageRgb img(int(d_.width), int(d_.height));
    const double inv = d_.nominalSamples ? 1.0 / double(d_.nominalSamples) : 0.0;
    parallelFor(pixelCount(), kChunk, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            img.pixels[i] = Vec3{float(d_.estimate[3 * i] * inv), float(d_.estimate[3 * i + 1] * inv),
                                 float(d_.estimate[3 * i + 2] * inv)};
    });
    return img;
}

std::uint32_t PixelAccumulator::samplesTaken(std::size_t i) const {
    return d_.adaptive ? d_.count[i] : std::uint32_t(d_.nominalSamples);
}

Vec3 PixelAccumulator::rawMean(std::size_t i) const {
    const std::uint32_t n = samplesTaken(i);
    if (n == 0) return Vec3{0.0f};
    const std::vector<double>& sums = d_.adaptive ? d_.raw : d_.estimate;
    return Vec3{float(sums[3 * i] / n), float(sums[3 * i + 1] / n), float(sums[3 * i + 2] / n)};
}

double PixelAccumulator::meanLuminanceVariance(std::size_t i) const {
    const double n = samplesTaken(i);
    if (n < 2) return 0.0;
    const std::vector<double>& sums = d_.adaptive ? d_.raw : d_.estimate;
    const double sumY = luminanceOf(&sums[3 * i]);
    const double sampleVariance = std::max(0.0, (d_.squares[i] - sumY * sumY / n) / (n - 1));
    return sampleVariance / n;
}

}  // namespace penumbra
