#include "render/env_table.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

double envTexelSolidAngle(std::uint32_t y, std::uint32_t width, std::uint32_t height) {
    constexpr double kPi = 3.14159265358979323846;
    const double theta0 = kPi * y / height, theta1 = kPi * (y + 1) / height;
    return 2 * kPi / width * (std::cos(theta0) - std::cos(theta1));
}

EnvTable buildEnvTable(const EnvironmentMap& map) {
    EnvTable t;
    t.width = std::uint32_t(map.width);
    t.height = std::uint32_t(map.height);
    const std::size_t n = std::size_t(t.width) * t.height;
    t.radiance.resize(n);
    t.alias.resize(n);
    std::vector<double> density(n);  // what the pdf is proportional to, per unit solid angle
    std::vector<double> rowSolidAngle(t.height);
    double total = 0;  // integral of density over the sphere
    for (std::uint32_t y = 0; y < t.height; ++y) {
        rowSolidAngle[y] = envTexelSolidAngle(y, t.width, t.height);
        double row = 0;
        for (std::uint32_t x = 0; x < t.width; ++x) {
            const std::size_t i = std::size_t(y) * t.width + x;
            const Vec3 L = map.radiance[i];
            t.radiance[i] = Vec4{L.x, L.y, L.z, 0.0f};
            density[i] = luminance(L);
            row += density[i];
        }
        total += row * rowSolidAngle[y];
    }
    if (!(total > 0)) {
        std::fill(density.begin(), density.end(), 1.0);
        total = 4 * 3.14159265358979323846;
    }

    // Vose: scaled pmfs below 1 are "small" and get topped up by a "large" one.
    std::vector<double> scaled(n);
    std::vector<std::uint32_t> small, large;
    small.reserve(n);
    large.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double pmf = density[i] * rowSolidAngle[i / t.width] / total;
        scaled[i] = pmf * double(n);
        t.alias[i] = {1.0f, std::uint32_t(i), float(density[i] / total), 0.0f};
        (scaled[i] < 1.0 ? small : large).push_back(std::uint32_t(i));
    }
    while (!small.empty() && !large.empty()) {
        const std::uint32_t s = small.back(), l = large.back();
        small.pop_back();
        t.alias[s].threshold = float(scaled[s]);
        t.alias[s].alias = l;
        scaled[l] -= 1.0 - scaled[s];
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // Whatever is left is 1 up to rounding: keep it whole.
    for (std::uint32_t i : small) t.alias[i].threshold = 1.0f;
    for (std::uint32_t i : large) t.alias[i].threshold = 1.0f;
    return t;
}

}  // namespace penumbra
