// Pearson's chi-square goodness-of-fit test over histogram bins, with small expected counts
// pooled (as pbrt-v4's and Mitsuba's sampling tests do), and its p-value.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

namespace penumbra::test {

// Regularised upper incomplete gamma function Q(a, x): a power series below x = a + 1, a
// continued fraction (modified Lentz) above it. Accurate to ~1e-12 for the a, x tests use.
inline double gammaQ(double a, double x) {
    if (x <= 0) return 1.0;
    const double logPrefix = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 100000 && std::abs(term) > std::abs(sum) * 1e-15; ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return 1.0 - sum * std::exp(logPrefix);
    }
    const double tiny = 1e-300;
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1) < 1e-15) break;
    }
    return std::exp(logPrefix) * h;
}

struct ChiSquareResult {
    double statistic = 0;
    int degreesOfFreedom = 0;
    double pValue = 1;
    bool observedWhereImpossible = false;  // samples in a bin whose expected count is zero
};

// observed[i] samples fell in bin i where expected[i] were expected. Bins expecting fewer than
// minExpected are pooled into one (dropped if the pool is still too small).
inline ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                                     double minExpected = 5.0) {
    ChiSquareResult r;
    double pooledObserved = 0, pooledExpected = 0;
    int bins = 0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] <= 0) {
            if (observed[i] > 0) r.observedWhereImpossible = true;
            continue;
        }
        if (expected[i] < minExpected) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            continue;
        }
        const double diff = observed[i] - expected[i];
        r.statistic += diff * diff / expected[i];
        ++bins;
    }
    if (pooledExpected >= minExpected) {
        const double diff = pooledObserved - pooledExpected;
        r.statistic += diff * diff / pooledExpected;
        ++bins;
    }
    r.degreesOfFreedom = bins - 1;
    r.pValue = r.degreesOfFreedom > 0 ? gammaQ(0.5 * r.degreesOfFreedom, 0.5 * r.statistic) : 1.0;
    return r;
}

// The per-test significance that keeps the family-wise rate at alpha over `tests` tests (Sidak).
inline double sidakAlpha(double alpha, int tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

}  // namespace penumbra::test
