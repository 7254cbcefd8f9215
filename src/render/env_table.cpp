#include "render/env_table.h"
#include "shared/constants.h"

#include <cmath>
#include <memory>

namespace penumbra {
namespace {
}

double envTexelSolidAngle(std::uint32_t y, std::uint32_t width, std::uint32_t height) {
    const double theta0 = kPi * y / height, theta1 = kPi * (y + 1) / height;
    return 2 * kPi / width * (std::cos(theta0) - std::cos(theta1));
}

// A 4096 x 2048 map is 8 Mi texels, and the cost is memory traffic, so every array is written
// once (push_back into reserved vectors, no zero fill first) and Vose's bookkeeping is small:
// the scaled probabilities live in the threshold fields, and one index array holds both work
// lists (small from the front, large from the back).
EnvTable buildEnvTable(const EnvironmentMap& map) {
    EnvTable t;
    const std::uint32_t w = std::uint32_t(map.width), h = std::uint32_t(map.height);
    t.width = w;
    t.height = h;
    const std::size_t n = std::size_t(w) * h;
    t.radiance.reserve(n);
    t.alias.reserve(n);
    std::vector<double> rowSolidAngle(h);
    // Pass 1: radiance for the GPU, luminance (kept in .pdf for now), and their integral.
    double total = 0;
    for (std::uint32_t y = 0; y < h; ++y) {
        rowSolidAngle[y] = envTexelSolidAngle(y, w, h);
        double rowSum = 0;
        for (std::size_t i = std::size_t(y) * w; i < std::size_t(y + 1) * w; ++i) {
            const Vec3 L = map.radiance[i];
            t.radiance.push_back(Vec4{L.x, L.y, L.z, 0.0f});
            const float lum = luminance(L);
            t.alias.push_back({0.0f, std::uint32_t(i), lum, 0.0f});
            rowSum += lum;
        }
        total += rowSum * rowSolidAngle[y];
    }
    const bool black = !(total > 0);
    if (black) total = 4 * kPi;  // sample uniformly over the sphere instead

    // Pass 2: pdf = density / total (constant over a texel); threshold = pmf * n for now.
    std::unique_ptr<std::uint32_t[]> work(new std::uint32_t[n]);
    std::size_t smallCount = 0, largeCount = 0;
    for (std::uint32_t y = 0; y < h; ++y) {
        const double toScaled = rowSolidAngle[y] / total * double(n);
        for (std::size_t i = std::size_t(y) * w; i < std::size_t(y + 1) * w; ++i) {
            shader::EnvAlias& a = t.alias[i];
            const double density = black ? 1.0 : double(a.pdf);
            a.pdf = float(density / total);
            a.threshold = float(density * toScaled);
            if (a.threshold < 1.0f)
                work[smallCount++] = std::uint32_t(i);
            else
                work[n - 1 - largeCount++] = std::uint32_t(i);
        }
    }
    // Vose: each small entry keeps its own share and is topped up to 1 by the large entry on top
    // of its list. That entry's remainder is carried in a double while it gives, so thousands of
    // subtractions do not accumulate float rounding.
    double remainder = largeCount ? double(t.alias[work[n - largeCount]].threshold) : 0.0;
    while (smallCount > 0 && largeCount > 0) {
        const std::uint32_t s = work[--smallCount], l = work[n - largeCount];
        t.alias[s].alias = l;  // t.alias[s].threshold already holds its scaled pmf
        remainder -= 1.0 - double(t.alias[s].threshold);
        if (remainder < 1.0) {
            t.alias[l].threshold = float(remainder);
            --largeCount;
            work[smallCount++] = l;
            if (largeCount) remainder = double(t.alias[work[n - largeCount]].threshold);
        }
    }
    // Whatever is left is 1 up to rounding: keep it whole.
    for (std::size_t k = 0; k < smallCount; ++k) t.alias[work[k]].threshold = 1.0f;
    for (std::size_t k = 0; k < largeCount; ++k) t.alias[work[n - 1 - k]].threshold = 1.0f;
    return t;
}

}  // namespace penumbra
