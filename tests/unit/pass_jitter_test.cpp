// The sub-pixel positions of shared camera rays (shaders/shared/pass_jitter.h): consecutive passes
// cover the pixel evenly, far more evenly than independent random positions, and over many pixels
// each pass's position is uniform (what keeps the mean unbiased).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "shared/types.h"
#include "shared/pass_jitter.h"

namespace penumbra {
namespace {

// The largest difference between the count in any cell of a cells x cells grid and the count
// a perfectly even spread would put there.
template <class Point>
double worstCellError(int points, int cells, Point&& point) {
    std::vector<int> counts(cells * cells, 0);
    for (int n = 0; n < points; ++n) {
        const Vec2 p = point(n);
        EXPECT_GE(p.x, 0.0f);
        EXPECT_LT(p.x, 1.0f);
        EXPECT_GE(p.y, 0.0f);
        EXPECT_LT(p.y, 1.0f);
        ++counts[int(p.y * cells) * cells + int(p.x * cells)];
    }
    const double even = double(points) / (cells * cells);
    double worst = 0;
    for (int c : counts) worst = std::max(worst, std::abs(c - even));
    return worst;
}

TEST(PassJitter, ConsecutivePassesCoverThePixelEvenly) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int pixel = 0; pixel < 20; ++pixel) {
        const std::uint32_t rx = rng(), ry = rng(), first = rng() % 100000;
        // 64 passes over a 4x4 grid: 4 a cell if perfectly even. Independent random points
        // miss that by 4 or more in most pixels; R2 points stay within 2 from any start.
        const double r2 = worstCellError(64, 4, [&](int n) { return shader::passJitter(rx, ry, first + n); });
        EXPECT_LE(r2, 2.0) << "pixel " << pixel;
        // 256 passes over 8x8: the same.
        EXPECT_LE(worstCellError(256, 8, [&](int n) { return shader::passJitter(rx, ry, first + n); }), 2.0);
    }
    // The check has teeth: independent uniform points fail it.
    int randomFailures = 0;
    for (int pixel = 0; pixel < 20; ++pixel)
        randomFailures += worstCellError(64, 4, [&](int) { return Vec2{u(rng), u(rng)}; }) > 2.0;
    EXPECT_GE(randomFailures, 10);
}

TEST(PassJitter, EachPassIsUniformOverRandomRotations) {
    // One pass, many pixels (rotations): a chi-square test of the positions over a 4x4 grid.
    std::mt19937 rng(11);
    for (std::uint32_t pass : {0u, 1u, 37u, 1000003u}) {
        constexpr int kPixels = 16000, kCells = 16;
        std::array<int, kCells> counts{};
        for (int i = 0; i < kPixels; ++i) {
            const Vec2 p = shader::passJitter(rng(), rng(), pass);
            ++counts[int(p.y * 4) * 4 + int(p.x * 4)];
        }
        double chi2 = 0;
        for (int c : counts) chi2 += (c - kPixels / 16.0) * (c - kPixels / 16.0) / (kPixels / 16.0);
        EXPECT_LT(chi2, 37.7) << "pass " << pass;  // 15 degrees of freedom, p = 0.001
    }
}

}  // namespace
}  // namespace penumbra
