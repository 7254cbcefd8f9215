// Chi-square goodness of fit of every BSDF sampling routine against its own pdf, on the real
// shader code: samples are binned over (cos theta, phi) of the whole sphere, and each bin's
// expected count is the pdf integrated over the bin numerically (the kernel's bsdfPdf on a grid
// of points inside it). Fails on p < 0.01, Sidak-corrected over all cases.
#include <cmath>
#include <sstream>

#include "bsdf_kernel.h"
#include "chi_square.h"
#include "gpu_fixture.h"
#include "shared/constants.h"

namespace penumbra::test {
namespace {

constexpr int kCosBins = 80, kPhiBins = 80;
constexpr std::uint32_t kSamples = 250000;

struct Chi2Case {
    std::string name;
    Material material;
    float cosThetaO;
    bool entering = true;
};

std::vector<Chi2Case> chi2Cases() {
    std::vector<Chi2Case> cases;
    for (float c : {0.95f, 0.5f, 0.15f}) {
        std::string at = "_cos" + std::to_string(int(c * 100));
        cases.push_back({"diffuse" + at, diffuseMaterial(Vec3{0.7f}), c});
        for (float r : {0.35f, 0.7f}) {
            std::string rough = "_rough" + std::to_string(int(r * 100));
            cases.push_back({"conductor" + rough + at, conductorMaterial(Vec3{0.9f, 0.6f, 0.3f}, r), c});
            cases.push_back({"plastic" + rough + at, plasticMaterial(Vec3{0.5f, 0.2f, 0.8f}, r), c});
            cases.push_back({"glass_in" + rough + at, glassMaterial(r, 1.5f), c, true});
            cases.push_back({"glass_out" + rough + at, glassMaterial(r, 1.5f), c, false});
        }
    }
    return cases;
}

int binOf(Vec3 w) {
    int ci = std::clamp(int((w.z + 1.0f) * 0.5f * kCosBins), 0, kCosBins - 1);
    float phi = std::atan2(w.y, w.x);
    if (phi < 0) phi += 2 * kPiF;
    int pi = std::clamp(int(phi / (2 * kPiF) * kPhiBins), 0, kPhiBins - 1);
    return ci * kPhiBins + pi;
}

// Expected sample count per bin: N times the pdf integrated over the bin by 4 x 4-point
// Gauss-Legendre quadrature (d omega = d cos theta d phi, so the rule needs no Jacobian), which
// is accurate for the smooth parts of narrow lobes. The pdf of rough refraction ends with a jump
// (microfacets seen edge-on have nonzero density), where no fixed rule is accurate: cells whose
// nodes are partly zero, partly not, are split in four, down to 1/64 of a bin.
std::vector<double> expectedCounts(BsdfKernel& kernel, Vec3 wo, bool entering, double samples) {
    // Nodes on [0, 1] and their weights (summing to 1).
    const double nodes[4] = {0.5 - 0.5 * 0.8611363115940526, 0.5 - 0.5 * 0.3399810435848563,
                             0.5 + 0.5 * 0.3399810435848563, 0.5 + 0.5 * 0.8611363115940526};
    const double weights[4] = {0.5 * 0.3478548451374538, 0.5 * 0.6521451548625461, 0.5 * 0.6521451548625461,
                               0.5 * 0.3478548451374538};
    struct Cell {
        int bin;
        double cos0, cos1, phi0, phi1;
        int depth;
    };
    std::vector<Cell> cells;
    for (int ci = 0; ci < kCosBins; ++ci)
        for (int pi = 0; pi < kPhiBins; ++pi)
            cells.push_back({ci * kPhiBins + pi, -1.0 + 2.0 * ci / kCosBins, -1.0 + 2.0 * (ci + 1) / kCosBins,
                             2 * kPiF * pi / kPhiBins, 2 * kPiF * (pi + 1) / kPhiBins, 0});
    std::vector<double> expected(kCosBins * kPhiBins, 0.0);
    while (!cells.empty()) {
        std::vector<shader::BsdfTestQuery> queries;
        for (const Cell& c : cells)
            for (int a = 0; a < 4; ++a)
                for (int b = 0; b < 4; ++b) {
                    float ct = float(c.cos0 + (c.cos1 - c.cos0) * nodes[a]);
                    float phi = float(c.phi0 + (c.phi1 - c.phi0) * nodes[b]);
                    queries.push_back({wo, entering ? 1u : 0u, localDirection(ct, phi), 0});
                }
        auto results = kernel.eval(queries);
        std::vector<Cell> split;
        for (std::size_t k = 0; k < cells.size(); ++k) {
            const Cell& c = cells[k];
            double integral = 0;
            int zeros = 0;
            for (int j = 0; j < 16; ++j) {
                const double pdf = results[k * 16 + std::size_t(j)].pdf;
                integral += pdf * weights[j / 4] * weights[j % 4];
                zeros += pdf > 0 ? 0 : 1;
            }
            if (zeros > 0 && zeros < 16 && c.depth < 6) {
                const double cm = 0.5 * (c.cos0 + c.cos1), pm = 0.5 * (c.phi0 + c.phi1);
                split.push_back({c.bin, c.cos0, cm, c.phi0, pm, c.depth + 1});
                split.push_back({c.bin, cm, c.cos1, c.phi0, pm, c.depth + 1});
                split.push_back({c.bin, c.cos0, cm, pm, c.phi1, c.depth + 1});
                split.push_back({c.bin, cm, c.cos1, pm, c.phi1, c.depth + 1});
                continue;
            }
            expected[std::size_t(c.bin)] += integral * (c.cos1 - c.cos0) * (c.phi1 - c.phi0) * samples;
        }
        cells = std::move(split);
    }
    return expected;
}

void PrintTo(const Chi2Case& c, std::ostream* os) { *os << c.name; }

class BsdfChi2Test : public GpuTest, public ::testing::WithParamInterface<Chi2Case> {};

TEST_P(BsdfChi2Test, SamplesFollowThePdf) {
    const Chi2Case& c = GetParam();
    BsdfKernel kernel(*ctx, c.material);
    const Vec3 wo = localDirection(c.cosThetaO, 0.7f);
    auto samples = kernel.sample(wo, c.entering, kSamples, 17);

    std::vector<double> observed(kCosBins * kPhiBins, 0.0);
    std::vector<shader::BsdfTestQuery> checks;
    for (const auto& s : samples) {
        ASSERT_EQ(s.isDelta, 0u) << "a rough material produced a delta sample";
        if (!(s.pdf > 0)) continue;  // a lost sample: its density is missing from the pdf too
        ASSERT_TRUE(std::isfinite(s.pdf) && isFinite(s.value) && minComponent(s.value) >= 0) << c.name;
        observed[binOf(s.wi)] += 1;
        if (checks.size() < 2000) checks.push_back({wo, c.entering ? 1u : 0u, s.wi, 0});
    }
    // Sampling, eval and pdf agree: the weight is f cos / pdf at the sampled direction.
    auto evals = kernel.eval(checks);
    int sampleIndex = 0;
    for (std::size_t i = 0; i < checks.size(); ++sampleIndex) {
        const auto& s = samples[std::size_t(sampleIndex)];
        if (!(s.pdf > 0)) continue;
        EXPECT_NEAR(evals[i].pdf, s.pdf, 1e-3f * s.pdf) << c.name << " sample " << sampleIndex;
        Vec3 expectedWeight = evals[i].value * (std::abs(s.wi.z) / evals[i].pdf);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(s.value[k], expectedWeight[k], 1e-3f * std::max(1.0f, expectedWeight[k])) << c.name;
        ++i;
    }

    auto expected = expectedCounts(kernel, wo, c.entering, kSamples);
    ChiSquareResult r = chiSquareTest(observed, expected);
    EXPECT_FALSE(r.observedWhereImpossible) << c.name << ": samples where the pdf is zero";
    const double alpha = sidakAlpha(0.01, int(chi2Cases().size()));
    EXPECT_GE(r.pValue, alpha) << c.name << ": chi2 = " << r.statistic << " with " << r.degreesOfFreedom
                               << " degrees of freedom";
    EXPECT_GT(r.degreesOfFreedom, 10) << c.name << ": too few populated bins for the test to mean much";
}

INSTANTIATE_TEST_SUITE_P(Lobes, BsdfChi2Test, ::testing::ValuesIn(chi2Cases()),
                         [](const ::testing::TestParamInfo<Chi2Case>& p) { return p.param.name; });

// The statistics helper itself, against closed forms: for 2 degrees of freedom p = exp(-x / 2);
// for 1, p = erfc(sqrt(x / 2)).
TEST(ChiSquare, PValuesMatchClosedForms) {
    for (double x : {0.1, 1.0, 3.0, 10.0, 40.0}) {
        EXPECT_NEAR(gammaQ(1.0, 0.5 * x), std::exp(-0.5 * x), 1e-12);
        EXPECT_NEAR(gammaQ(0.5, 0.5 * x), std::erfc(std::sqrt(0.5 * x)), 1e-10);
    }
    // A histogram far from its expectation fails, one equal to it passes.
    std::vector<double> expected(50, 100.0), same = expected, skewed = expected;
    for (std::size_t i = 0; i < skewed.size(); ++i) skewed[i] += (i % 2 ? 30.0 : -30.0);
    EXPECT_GT(chiSquareTest(same, expected).pValue, 0.99);
    EXPECT_LT(chiSquareTest(skewed, expected).pValue, 1e-6);
}

}  // namespace
}  // namespace penumbra::test
