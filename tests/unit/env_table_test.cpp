// The environment's sampling table on the CPU: the alias table reproduces each texel's pmf
// exactly, pmfs are luminance x solid angle, and the stored pdf integrates to 1 over the sphere.
// Also the direction <-> (u, v) mapping both ways and the sky generator.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.h"
#include "render/env_table.h"
#include "scene/environment.h"
#include "scene/io/env_sky.h"
#include "shared/constants.h"

namespace penumbra {
namespace {


EnvironmentMap randomMap(int w, int h, unsigned seed) {
    EnvironmentMap m;
    m.name = "random";
    m.width = w;
    m.height = h;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < w * h; ++i) {
        float scale = u(rng) < 0.2f ? 0.0f : (u(rng) < 0.05f ? 1000.0f : 1.0f);  // black texels and hot spots
        m.radiance.push_back(Vec3{u(rng), u(rng), u(rng)} * scale);
    }
    return m;
}

// The probability of picking each texel implied by the table (slot uniform, then threshold).
std::vector<double> impliedPmf(const EnvTable& t) {
    const std::size_t n = t.alias.size();
    std::vector<double> p(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const double keep = std::clamp(double(t.alias[i].threshold), 0.0, 1.0);
        p[i] += keep / double(n);
        p[t.alias[i].alias] += (1 - keep) / double(n);
    }
    return p;
}

TEST(EnvTable, AliasTableReproducesLuminanceTimesSolidAngle) {
    for (auto [w, h] : {std::pair{16, 8}, std::pair{7, 3}, std::pair{64, 32}}) {
        EnvironmentMap m = randomMap(w, h, unsigned(w));
        EnvTable t = buildEnvTable(m);
        ASSERT_EQ(t.alias.size(), std::size_t(w * h));
        double total = 0;
        for (int i = 0; i < w * h; ++i) total += luminance(m.radiance[i]) * envTexelSolidAngle(i / w, w, h);
        std::vector<double> p = impliedPmf(t);
        double sum = 0, pdfIntegral = 0;
        for (int i = 0; i < w * h; ++i) {
            const double omega = envTexelSolidAngle(i / w, w, h);
            const double expected = luminance(m.radiance[i]) * omega / total;
            // Thresholds are floats: the entries left at the end absorb the rounding of the sum
            // (about 1e-7 of the largest scaled pmf each), a few parts per million at most.
            EXPECT_NEAR(p[i], expected, 2e-5 * std::max(expected, 1.0 / (w * h))) << w << "x" << h << " texel " << i;
            EXPECT_NEAR(t.alias[i].pdf, expected / omega, 1e-5 * expected / omega + 1e-12);
            if (expected == 0) {
                EXPECT_EQ(p[i], 0.0) << "a black texel can be picked";
            }
            sum += p[i];
            pdfIntegral += t.alias[i].pdf * omega;
            EXPECT_EQ(t.radiance[i].x, m.radiance[i].x);
        }
        EXPECT_NEAR(sum, 1.0, 1e-9);
        EXPECT_NEAR(pdfIntegral, 1.0, 1e-5);
    }
}

TEST(EnvTable, BlackMapFallsBackToUniformOverTheSphere) {
    EnvironmentMap m{"black", 8, 4, std::vector<Vec3>(32, Vec3{0})};
    EnvTable t = buildEnvTable(m);
    for (const auto& e : t.alias) EXPECT_NEAR(e.pdf, 1.0 / (4 * kPi), 1e-7);
}

TEST(EnvTable, SolidAnglesCoverTheSphere) {
    double sum = 0;
    for (std::uint32_t y = 0; y < 9; ++y) sum += 13 * envTexelSolidAngle(y, 13, 9);
    EXPECT_NEAR(sum, 4 * kPi, 1e-12);
}

TEST(EnvMapping, DirectionAndUvAreInversesWithTheDocumentedAxes) {
    // u = 0.5 is -z, u = 0.75 is +x, v = 0 is +y.
    Vec3 d = environmentDirection(0.5, 0.5);
    EXPECT_NEAR(d.z, -1.0f, 1e-6f);
    d = environmentDirection(0.75, 0.5);
    EXPECT_NEAR(d.x, 1.0f, 1e-6f);
    EXPECT_NEAR(environmentDirection(0.3, 0.0).y, 1.0f, 1e-6f);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.001, 0.999);
    for (int i = 0; i < 1000; ++i) {
        const double a = u(rng), b = u(rng);
        Vec2 uv = environmentUv(environmentDirection(a, b));
        EXPECT_NEAR(uv.x, a, 1e-5);
        EXPECT_NEAR(uv.y, b, 1e-5);
    }
    // Rotation by +90 degrees takes -z (the map's centre) to -x.
    Vec3 r = rotateAboutY(Vec3{0, 0, -1}, kPi / 2);
    EXPECT_NEAR(r.x, -1.0f, 1e-6f);
}

TEST(EnvSky, SunIsADiskWhereAskedAndTheGroundIsLitBySunAndSky) {
    SkyParams p;
    p.sunElevationDegrees = 30;
    p.sunAzimuthDegrees = 90;  // toward +x
    p.width = 64;
    p.height = 32;
    Sky sky = makeSky(p);
    const Vec3 toSun = -sky.sun.direction;
    EXPECT_NEAR(toSun.x, std::cos(kPi / 6), 1e-5);
    EXPECT_NEAR(toSun.y, 0.5, 1e-5);
    EXPECT_NEAR(sky.sun.angularRadius, 0.27 * kPi / 180, 1e-7);
    EXPECT_EQ(sky.sun.type, LightType::Directional);
    // Sunlight through 2 air masses: tens of klux, reddened (blue scatters more).
    const double lux = sky.sun.intensity / (kPi * 1e-5);
    EXPECT_GT(lux, 40000);
    EXPECT_LT(lux, 128000);
    EXPECT_GT(sky.sun.color.x, sky.sun.color.z);

    // Zenith luminance matches Preetham's formula (T = 3, theta_s = 60 deg), in cd/m^2.
    const double chi = (4.0 / 9 - 3.0 / 120) * (kPi - 2 * kPi / 3);
    const double zenith = 1000 * ((4.0453 * 3 - 4.9710) * std::tan(chi) - 0.2155 * 3 + 2.4192);
    const Vec3 top = sky.map.radiance[p.width / 2];  // first row: within 3 degrees of the zenith
    EXPECT_NEAR(luminance(top) / (kPi * 1e-5), zenith, 0.05 * zenith);
    // The sky is brighter toward the sun than away from it, at the same elevation.
    auto at = [&](double u, double v) { return luminance(sky.map.radiance[int(v * p.height) * p.width + int(u * p.width)]); };
    EXPECT_GT(at(0.75, 0.3), at(0.25, 0.3));
    // Every ground texel has the same radiance: albedo / pi times the irradiance from above.
    const Vec3 ground = sky.map.radiance[std::size_t(p.width) * (p.height - 1)];
    EXPECT_GT(luminance(ground), 0);
    EXPECT_LT(luminance(ground), p.groundAlbedo / kPi * (luminance(sky.sun.color) * sky.sun.intensity * 0.5 + kPi * luminance(top) * 3));
    EXPECT_THROW(makeSky(SkyParams{-5}), Error);
}

TEST(EnvSky, DistantLightsFollowRotationAndIntensity) {
    Environment env;
    Sky sky = makeSky(SkyParams{});
    env.sun = sky.sun;
    env.rotationDegrees = 90;
    env.intensity = 3;
    std::vector<Light> lights = distantLights(env);
    ASSERT_EQ(lights.size(), 1u);
    EXPECT_NEAR(lights[0].intensity, 3 * sky.sun.intensity, 1e-6);
    Vec3 expected = rotateAboutY(sky.sun.direction, kPi / 2);
    EXPECT_NEAR(lights[0].direction.x, expected.x, 1e-6);
    EXPECT_NEAR(lights[0].direction.z, expected.z, 1e-6);
}

}  // namespace
}  // namespace penumbra
