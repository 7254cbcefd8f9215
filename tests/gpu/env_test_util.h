// Shared by the environment GPU tests: hand-made maps, a floor scene, and chi-square p-values.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "render_helpers.h"
#include "scene/presets/mesh_builder.h"
#include "scene/scene.h"
#include "shared/constants.h"

namespace penumbra::test {


// A small map with a bright spot (two texels 200x the rest) and a vertical and horizontal
// gradient, coloured so that channels differ.
inline EnvironmentMap spotAndGradientMap(int w = 16, int h = 8) {
    EnvironmentMap m;
    m.name = "spot";
    m.width = w;
    m.height = h;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float g = 0.05f + float(y) / float(h) + 0.5f * float(x) / float(w);
            m.radiance.push_back(Vec3{g, 0.5f * g, 0.25f + g});
        }
    m.radiance[std::size_t(2) * w + 5] = Vec3{200, 150, 100};
    m.radiance[std::size_t(2) * w + 6] = Vec3{100, 200, 50};
    return m;
}

// A diffuse floor of albedo `albedo` at y = 0 (100 m square, facing up) seen from 3 m above.
inline Scene envFloorScene(float albedo) { return diffuseFloorScene(albedo, {0, 3, 0}, {0, 0, -1}, 20.0f); }

// Irradiance on an upward-facing plane from a map (nearest lookup, rows of even-height maps end
// exactly at the horizon): sum of L times the projected solid angle of each upper texel.
inline Vec3 upperIrradiance(const EnvironmentMap& m, float intensity) {
    Vec3 e{0};
    for (int y = 0; y < m.height; ++y) {
        const double t0 = kPi * y / m.height, t1 = std::min(kPi / 2, kPi * (y + 1) / m.height);
        if (t0 >= kPi / 2) break;
        const double projected = 2 * kPi / m.width * 0.5 * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0));
        for (int x = 0; x < m.width; ++x) e = e + m.radiance[std::size_t(y) * m.width + x] * float(projected);
    }
    return e * intensity;
}

// Upper tail of the chi-square distribution with k degrees of freedom (regularized incomplete
// gamma Q(k/2, x/2): series below the mean, Lentz's continued fraction above).
inline double chiSquareTail(double x, double k) {
    const double a = k / 2, z = x / 2;
    if (z <= 0) return 1.0;
    const double logPrefix = a * std::log(z) - z - std::lgamma(a);
    if (z < a + 1) {
        double term = 1 / a, sum = term;
        for (int n = 1; n < 10000 && term > sum * 1e-15; ++n) sum += term *= z / (a + n);
        return 1 - std::exp(logPrefix) * sum;
    }
    double b = z + 1 - a, c = 1e300, d = 1 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        const double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::abs(d) < 1e-300) d = 1e-300;
        c = b + an / c;
        if (std::abs(c) < 1e-300) c = 1e-300;
        d = 1 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1) < 1e-15) break;
    }
    return std::exp(logPrefix) * h;
}

// Pearson's statistic over bins, pooling those expected below 5 into one; returns the p-value.
inline double chiSquarePValue(const std::vector<double>& observed, const std::vector<double>& expected) {
    double chi2 = 0, pooledObs = 0, pooledExp = 0;
    int dof = -1;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] < 5) {
            pooledObs += observed[i];
            pooledExp += expected[i];
            continue;
        }
        chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++dof;
    }
    if (pooledExp > 0) {
        chi2 += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
        ++dof;
    } else if (pooledObs > 0) {
        return 0.0;  // samples where none were expected
    }
    return chiSquareTail(chi2, std::max(dof, 1));
}

}  // namespace penumbra::test
