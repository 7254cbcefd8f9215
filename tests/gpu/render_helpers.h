// Statistics over a renderer's accumulation buffer, for tests with tolerances derived from the
// sample count.
#pragma once

#include <cmath>
#include <vector>

#include "core/vec.h"

namespace penumbra::test {

struct PixelStats {
    double mean;    // mean luminance of the pixel
    double stderr;  // standard error of that mean, from the sample variance
};

inline PixelStats pixelStats(const Vec4& sums, double samples) {
    double mean = luminance(Vec3{sums.x, sums.y, sums.z}) / samples;
    double variance = std::max(0.0, sums.w / samples - mean * mean) * samples / std::max(1.0, samples - 1);
    return {mean, std::sqrt(variance / samples)};
}

// The normal quantile that keeps the family-wise false-alarm rate at `alpha` over `tests`
// independent tests (Sidak), by bisection on the complementary error function.
inline double sidakZ(double alpha, std::size_t tests) {
    double perTest = 1.0 - std::pow(1.0 - alpha, 1.0 / double(tests));
    double lo = 0, hi = 40;
    for (int i = 0; i < 200; ++i) {
        double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > perTest ? lo : hi) = mid;
    }
    return hi;
}

}  // namespace penumbra::test
