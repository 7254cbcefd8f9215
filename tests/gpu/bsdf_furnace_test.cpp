// Energy and consistency properties of the real BSDF code:
//  - white furnace: with base colour 1, the mean sample weight (the directional albedo) is at
//    most 1, and exactly 1 for the lossless lobes (Lambert, mirror, smooth glass);
//  - the pdf integrates over the sphere to the fraction of samples that come from non-delta
//    lobes and are not lost (Monte Carlo over stratified uniform directions);
//  - reflection is reciprocal: f(wo, wi) = f(wi, wo).
#include <cmath>
#include <random>

#include "bsdf_kernel.h"
#include "gpu_fixture.h"
#include "render_helpers.h"
#include "shared/constants.h"

namespace penumbra::test {
namespace {


struct EnergyCase {
    std::string name;
    Material material;
    bool lossless;  // every sample's weight must be exactly 1
};

std::vector<EnergyCase> energyCases() {
    const Vec3 white{1.0f};
    return {
        {"diffuse", diffuseMaterial(white), true},
        {"mirror", conductorMaterial(white, 0.0f), true},
        {"smooth_glass", glassMaterial(0.0f, 1.5f), true},
        {"conductor_rough30", conductorMaterial(white, 0.3f), false},
        {"conductor_rough100", conductorMaterial(white, 1.0f), false},
        {"plastic_smooth", plasticMaterial(white, 0.0f), false},
        {"plastic_rough30", plasticMaterial(white, 0.3f), false},
        {"plastic_rough100", plasticMaterial(white, 1.0f), false},
        {"glass_rough30", glassMaterial(0.3f, 1.5f), false},
        {"glass_rough80_ior2", glassMaterial(0.8f, 2.0f), false},
        {"half_metal_rough50", [] {
             Material m = plasticMaterial(Vec3{1.0f}, 0.5f);
             m.metallic = 0.5f;
             return m;
         }(), false},
    };
}

void PrintTo(const EnergyCase& c, std::ostream* os) { *os << c.name; }

class BsdfEnergyTest : public GpuTest, public ::testing::WithParamInterface<EnergyCase> {};

// Mean and standard error of a sum of per-sample values.
struct MeanError {
    double mean, error;
};

MeanError meanError(double sum, double sumSquares, double n) {
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sumSquares / n - mean * mean) / (n - 1))};
}

// Stratified uniform directions over the whole sphere, for brute-force integrals (each stands
// for 4 pi / count steradians).
std::vector<shader::BsdfTestQuery> sphereQueries(Vec3 wo, bool entering, int strata, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<shader::BsdfTestQuery> queries;
    for (int i = 0; i < strata; ++i)
        for (int j = 0; j < strata; ++j)
            queries.push_back({wo, entering ? 1u : 0u,
                               localDirection(-1.0f + 2.0f * (i + u(rng)) / strata, 2 * kPiF * (j + u(rng)) / strata), 0});
    return queries;
}

// The directional albedo (mean sample weight) is at most 1, exactly 1 for lossless lobes, and
// its non-delta part equals the brute-force integral of f |cos| over the sphere.
TEST_P(BsdfEnergyTest, WhiteFurnaceReflectsAtMostOne) {
    const EnergyCase& c = GetParam();
    BsdfKernel kernel(*ctx, c.material);
    const std::uint32_t n = 60000;
    const double z = sidakZ(1e-3, energyCases().size() * 8 * 2);
    for (bool entering : {true, false}) {
        for (float cosTheta : {1.0f, 0.8f, 0.4f, 0.1f}) {
            const Vec3 wo = localDirection(cosTheta, 1.3f);
            auto samples = kernel.sample(wo, entering, n, 5);
            double sum = 0, sumSquares = 0, smoothSum = 0, smoothSquares = 0;
            for (const auto& s : samples) {
                ASSERT_TRUE(isFinite(s.value) && minComponent(s.value) >= 0) << c.name;
                const double w = luminance(s.value);
                sum += w;
                sumSquares += w * w;
                if (!s.isDelta) smoothSum += w, smoothSquares += w * w;
                if (c.lossless) {
                    ASSERT_NEAR(w, 1.0, 1e-5) << c.name << " at cos " << cosTheta;
                }
            }
            const MeanError albedo = meanError(sum, sumSquares, n);
            EXPECT_LE(albedo.mean, 1.0 + z * albedo.error + 1e-6) << c.name << " at cos " << cosTheta << " creates energy";

            const std::vector<shader::BsdfTestQuery> queries = sphereQueries(wo, entering, 300, 4);
            auto evals = kernel.eval(queries);
            double bruteSum = 0, bruteSquares = 0;
            for (std::size_t i = 0; i < evals.size(); ++i) {
                const double v = 4 * kPiF * luminance(evals[i].value) * std::abs(queries[i].wi.z);
                bruteSum += v;
                bruteSquares += v * v;
            }
            const MeanError smooth = meanError(smoothSum, smoothSquares, n);
            const MeanError brute = meanError(bruteSum, bruteSquares, double(evals.size()));
            EXPECT_NEAR(smooth.mean, brute.mean, z * std::hypot(smooth.error, brute.error) + 1e-4)
                << c.name << " at cos " << cosTheta << (entering ? " outside" : " inside")
                << ": sampling and eval disagree on the non-delta albedo";
        }
    }
}

TEST_P(BsdfEnergyTest, PdfIntegratesToTheShareOfNonDeltaSamples) {
    const EnergyCase& c = GetParam();
    const bool deltaOnly = c.name == "mirror" || c.name == "smooth_glass";  // the pdf must be zero everywhere
    BsdfKernel kernel(*ctx, c.material);
    const double z = sidakZ(1e-3, energyCases().size() * 2);
    for (float cosTheta : {0.9f, 0.3f}) {
        const Vec3 wo = localDirection(cosTheta, 0.4f);
        // Stratified uniform directions over the sphere: pdf * 4 pi estimates the integral.
        const std::vector<shader::BsdfTestQuery> queries = sphereQueries(wo, true, 400, 6);
        auto evals = kernel.eval(queries);
        double sum = 0, sumSquares = 0;
        for (const auto& e : evals) {
            const double v = 4 * kPiF * e.pdf;
            sum += v;
            sumSquares += v * v;
        }
        const double m = double(queries.size());
        const double integral = sum / m;
        // Stratification only lowers the variance, so the unstratified estimate bounds it.
        const double integralErr = std::sqrt(std::max(0.0, sumSquares / m - integral * integral) / (m - 1));

        const std::uint32_t n = 200000;
        auto samples = kernel.sample(wo, true, n, 9);
        double nonDelta = 0;
        for (const auto& s : samples) nonDelta += (s.pdf > 0 && !s.isDelta) ? 1 : 0;
        const double share = nonDelta / n;
        const double shareErr = std::sqrt(share * (1 - share) / n);
        EXPECT_NEAR(integral, share, z * std::hypot(integralErr, shareErr) + 1e-4)
            << c.name << " at cos " << cosTheta;
        if (!deltaOnly) {
            EXPECT_GT(share, 0.0) << c.name;
        }
    }
}

TEST_P(BsdfEnergyTest, ReflectionIsReciprocal) {
    const EnergyCase& c = GetParam();
    BsdfKernel kernel(*ctx, c.material);
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<shader::BsdfTestQuery> queries;
    for (int i = 0; i < 2000; ++i) {
        Vec3 a = localDirection(0.02f + 0.98f * u(rng), 2 * kPiF * u(rng));
        Vec3 b = localDirection(0.02f + 0.98f * u(rng), 2 * kPiF * u(rng));
        queries.push_back({a, 1u, b, 0});
        queries.push_back({b, 1u, a, 0});
    }
    auto evals = kernel.eval(queries);
    int nonzero = 0;
    for (std::size_t i = 0; i < evals.size(); i += 2) {
        const Vec3 f = evals[i].value, g = evals[i + 1].value;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(f[k], g[k], 1e-4f * std::max(1.0f, f[k])) << c.name << " pair " << i / 2;
        nonzero += maxComponent(f) > 0;
    }
    if (c.name != "mirror" && c.name != "smooth_glass") {
        EXPECT_GT(nonzero, 1000) << c.name;
    }
}

INSTANTIATE_TEST_SUITE_P(Materials, BsdfEnergyTest, ::testing::ValuesIn(energyCases()),
                         [](const ::testing::TestParamInfo<EnergyCase>& p) { return p.param.name; });

// The metallic-roughness texture (glTF: G = roughness, B = metallic, linear) scales the factors:
// a texel of G 0, B 1 turns a rough dielectric into a mirror (delta samples of weight F0 = base
// colour), and G 1, B 0 leaves a Lambertian (every weight equals the albedo, no delta samples).
TEST_F(GpuTest, MetallicRoughnessTextureSelectsTheLobes) {
    const Vec3 base{0.9f, 0.5f, 0.25f};
    for (bool mirror : {true, false}) {
        Texture t;
        t.name = "metallic-roughness";
        t.width = t.height = 1;
        t.srgb = false;
        t.rgba = {0, std::uint8_t(mirror ? 0 : 255), std::uint8_t(mirror ? 255 : 0), 255};
        Material m = diffuseMaterial(base);
        m.metallic = 1.0f;
        m.roughness = 1.0f;
        m.metallicRoughnessTexture.texture = 0;
        BsdfKernel kernel(*ctx, m, {t});
        for (const auto& s : kernel.sample(localDirection(1.0f, 0.0f), true, 256, 3)) {
            EXPECT_EQ(s.isDelta != 0, mirror);
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.value[k], base[k], 1e-5f) << (mirror ? "mirror" : "lambert");
        }
    }
}

// A Lambertian material's kernel (made without the glossy lobes and glass: PN_FEATURE_GLOSSY and
// PN_FEATURE_TRANSMISSION off, BsdfParams.lambertian) takes the diffuse lobe's own code, which
// must give what the whole mixture's code gives for the same material: f and the pdf for the
// same directions, and the same samples for the same random numbers, to the last few bits.
TEST_F(GpuTest, TheLambertianKernelGivesWhatTheWholeMixtureGives) {
    const Material m = diffuseMaterial(Vec3{0.7f, 0.45f, 0.2f});
    BsdfKernel lambertian(*ctx, m);
    BsdfKernel mixture(*ctx, m, {}, KernelSpec{});
    std::vector<shader::BsdfTestQuery> queries;
    for (float cosO : {1.0f, 0.7f, 0.2f, 0.01f})
        for (float cosI : {0.9f, 0.5f, 0.05f, -0.3f})
            for (float phi : {0.0f, 1.3f, 2.9f}) {
                shader::BsdfTestQuery q{};
                q.wo = localDirection(cosO, 0.4f);
                q.wi = localDirection(cosI, phi);
                q.entering = 1u;
                queries.push_back(q);
            }
    const auto a = lambertian.eval(queries), b = mixture.eval(queries);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_NEAR(a[i].pdf, b[i].pdf, 1e-6f * std::max(1.0f, b[i].pdf)) << "query " << i;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[i].value[k], b[i].value[k], 1e-6f) << "query " << i;
    }
    const auto sa = lambertian.sample(localDirection(0.6f, 0.3f), true, 512, 9);
    const auto sb = mixture.sample(localDirection(0.6f, 0.3f), true, 512, 9);
    ASSERT_EQ(sa.size(), sb.size());
    for (std::size_t i = 0; i < sa.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(sa[i].wi[k], sb[i].wi[k], 1e-6f) << "sample " << i;
            EXPECT_NEAR(sa[i].value[k], sb[i].value[k], 1e-5f) << "sample " << i;
        }
        EXPECT_NEAR(sa[i].pdf, sb[i].pdf, 1e-5f * std::max(1.0f, sb[i].pdf)) << "sample " << i;
        EXPECT_EQ(sa[i].isDelta, sb[i].isDelta);
    }
}

// Beer absorption's coefficient: light that travels the given distance keeps the given colour.
TEST(Absorption, CoefficientKeepsTheColourAtTheDistance) {
    Material m = glassMaterial(0.0f, 1.5f);
    m.absorptionColor = {0.5f, 0.25f, 1.0f};
    m.absorptionDistance = 2.0f;
    Vec3 sigma = absorptionCoefficient(m);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(std::exp(-sigma[k] * 2.0f), m.absorptionColor[k], 1e-6f);
    m.absorptionDistance = 0.0f;
    EXPECT_EQ(maxComponent(absorptionCoefficient(m)), 0.0f);
}

}  // namespace
}  // namespace penumbra::test
