// The alias table must pick each light with its pmf: checked exactly (the table's implied
// probabilities) and by a chi-square test of the same lookup the shader does.
#include <gtest/gtest.h>

#include <random>

#include "render/light_table.h"

namespace penumbra {
namespace {

// The probability that the shader's lookup (slot = floor(u n), keep if frac < threshold) picks
// each entry, computed exactly.
std::vector<double> impliedProbabilities(const std::vector<shader::LightAlias>& t) {
    std::vector<double> p(t.size(), 0.0);
    for (std::size_t i = 0; i < t.size(); ++i) {
        p[i] += t[i].threshold / double(t.size());
        p[t[i].alias] += (1.0 - t[i].threshold) / double(t.size());
    }
    return p;
}

TEST(LightTable, ImpliedProbabilitiesEqualNormalisedWeights) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 10.0);
    for (std::size_t n : {1u, 2u, 5u, 100u, 1000u}) {
        std::vector<std::uint32_t> tris(n);
        std::vector<double> w(n);
        double total = 0;
        for (std::size_t i = 0; i < n; ++i) {
            tris[i] = std::uint32_t(i * 3);
            w[i] = (i % 4 == 0) ? u(rng) * 100 : u(rng);
            total += w[i];
        }
        auto table = buildAliasTable(tris, w);
        ASSERT_EQ(table.size(), n);
        auto p = impliedProbabilities(table);
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_NEAR(p[i], w[i] / total, 1e-6) << "n " << n << " entry " << i;
            EXPECT_NEAR(table[i].pmf, w[i] / total, 1e-6);
            EXPECT_EQ(table[i].triangle, tris[i]);
        }
    }
}

TEST(LightTable, ZeroWeightsAreLeftOut) {
    std::vector<std::uint32_t> tris = {10, 11, 12};
    std::vector<double> w = {0.0, 2.0, 0.0};
    auto table = buildAliasTable(tris, w);
    ASSERT_EQ(table.size(), 1u);
    EXPECT_EQ(table[0].triangle, 11u);
    EXPECT_FLOAT_EQ(table[0].pmf, 1.0f);
    EXPECT_TRUE(buildAliasTable(tris, std::vector<double>{0, 0, 0}).empty());
}

TEST(LightTable, SampledFrequenciesPassChiSquare) {
    std::vector<std::uint32_t> tris = {0, 1, 2, 3, 4, 5, 6, 7};
    std::vector<double> w = {1, 2, 3, 4, 0.5, 8, 0.25, 16};
    auto table = buildAliasTable(tris, w);
    std::mt19937 rng(42);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const int draws = 200000;
    std::vector<int> counts(tris.size(), 0);
    for (int d = 0; d < draws; ++d) {
        float x = u(rng) * float(table.size());
        std::uint32_t slot = std::min<std::uint32_t>(std::uint32_t(x), std::uint32_t(table.size() - 1));
        const auto& e = (x - float(slot) < table[slot].threshold) ? table[slot] : table[table[slot].alias];
        counts[e.triangle]++;
    }
    double total = 0;
    for (double x : w) total += x;
    double chi2 = 0;
    for (std::size_t i = 0; i < w.size(); ++i) {
        double expected = draws * w[i] / total;
        chi2 += (counts[i] - expected) * (counts[i] - expected) / expected;
    }
    // 7 degrees of freedom: P(chi2 > 24.32) = 0.001.
    EXPECT_LT(chi2, 24.32);
}

}  // namespace
}  // namespace penumbra
