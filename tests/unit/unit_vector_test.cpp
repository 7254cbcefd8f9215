// The packed shading normals (shaders/shared/unit_vector.h): every direction comes back within
// the octahedral map's error bound, including the axes, the equator and the folded lower half.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shared/unit_vector.h"

namespace penumbra {
namespace {

// In double, and by atan2: acos of a float dot product near 1 is itself off by 3e-4 radians.
double angleBetween(Vec3 a, Vec3 b) {
    const double cx = double(a.y) * b.z - double(a.z) * b.y, cy = double(a.z) * b.x - double(a.x) * b.z,
                 cz = double(a.x) * b.y - double(a.y) * b.x;
    return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), double(a.x) * b.x + double(a.y) * b.y + double(a.z) * b.z);
}

TEST(UnitVector, RoundTripsWithinATenThousandthOfARadian) {
    std::vector<Vec3> dirs = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1},
                              {1, 1, 0}, {-1, 0, -1e-7f}, {0.3f, -0.2f, -5.0f}, {2, 3, -4}};
    std::mt19937 rng(7);
    std::normal_distribution<float> g;
    for (int i = 0; i < 100000; ++i) dirs.push_back({g(rng), g(rng), g(rng)});
    double worst = 0;
    for (const Vec3& d : dirs) {
        if (!(length(d) > 0)) continue;
        const Vec3 back = shader::unpackUnitVector(shader::packUnitVector(d));
        EXPECT_NEAR(length(back), 1.0f, 1e-6f);
        worst = std::max(worst, angleBetween(back, d));
    }
    EXPECT_LT(worst, 1e-4);
    EXPECT_GT(worst, 0.0) << "16 bits per coordinate cannot be exact everywhere";
}

TEST(UnitVector, ZeroAndNonFiniteVectorsPackAsUp) {
    const float nan = std::nanf("");
    for (Vec3 bad : {Vec3{0, 0, 0}, Vec3{nan, 0, 1}, Vec3{INFINITY, 0, 0}}) {
        const Vec3 back = shader::unpackUnitVector(shader::packUnitVector(bad));
        EXPECT_EQ(back.x, 0.0f);
        EXPECT_EQ(back.y, 0.0f);
        EXPECT_EQ(back.z, 1.0f);
    }
}

}  // namespace
}  // namespace penumbra
