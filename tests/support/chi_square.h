// Pearson's χ² goodness-of-fit test for samplers (host, tests only): a histogram of a sampler's output
// against the expected counts of its pdf. Follows pbrt-v4's bsdfs_test.cpp (cells expected below 5 pooled in
// order of expected count, dof = cells − 1, a sample in a cell of expected count 0 rejects unless it is
// below 1e-5 of the samples, Šidák-corrected significance) with the settings future-work-anchors.md §1 gives
// for pbrt and Mitsuba 3: 10⁶ samples, α = 0.01, Mitsuba's 101-cell resolution (chi2.py).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <string>
#include <vector>

namespace trazo {

constexpr int kChiSquareSamples = 1000000;
constexpr double kChiSquareSignificance = 0.01;
constexpr double kChiSquareMinExpected = 5.0;
// Mitsuba's SphericalDomain at res = 101: φ ∈ [−π, π) in 50 columns (101 / aspect 2) × cos θ ∈ [−1, 1] in
// 101 rows; its PlanarDomain over [−1, 1]²: 101 × 101.
constexpr int kChiSquareResolution = 101;
constexpr int kChiSquarePhiBins = 50;

// Q(a, x) = Γ(a, x)/Γ(a), the upper regularized incomplete gamma: the series below x = a + 1, Lentz's
// continued fraction above (Numerical Recipes §6.2), each to double precision.
inline double upperRegularizedGamma(double a, double x) {
    if (!(x > 0.0)) return 1.0;
    const double logPrefix = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 1000000 && term > sum * 1e-17; ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return std::max(0.0, 1.0 - sum * std::exp(logPrefix));
    }
    constexpr double kTiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 1000000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-16) break;
    }
    return std::exp(logPrefix) * h;
}

// P(χ²_dof ≥ statistic).
inline double chiSquarePValue(double statistic, int dof) { return upperRegularizedGamma(0.5 * dof, 0.5 * statistic); }

// The per-test level that keeps the family of `tests` independent tests at `alpha` (Šidák).
inline double sidakLevel(double alpha, int tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

struct ChiSquareResult {
    double statistic = 0.0;
    int dof = 0;
    double pValue = 0.0;
    std::string failure;  // why the null hypothesis was rejected outright (samples where none may fall), if so

    bool accepts(double level) const { return failure.empty() && dof > 0 && std::isfinite(pValue) && pValue >= level; }
};

// Observed counts against expected counts, cell by cell (both the same length; expected sums to the samples).
inline ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                                     double minExpected = kChiSquareMinExpected) {
    ChiSquareResult r;
    const double samples = std::accumulate(observed.begin(), observed.end(), 0.0);
    std::vector<size_t> order(expected.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
    double pooledObserved = 0.0, pooledExpected = 0.0;
    int cells = 0;
    for (size_t i : order) {
        if (expected[i] == 0.0) {
            if (observed[i] > samples * 1e-5)
                r.failure = std::to_string(observed[i]) + " samples in cell " + std::to_string(i) + " of expected count 0";
        } else if (expected[i] < minExpected || (pooledExpected > 0.0 && pooledExpected < minExpected)) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
        } else {
            const double d = observed[i] - expected[i];
            r.statistic += d * d / expected[i];
            ++cells;
        }
    }
    if (pooledExpected > 0.0) {
        const double d = pooledObserved - pooledExpected;
        r.statistic += d * d / pooledExpected;
        ++cells;
    }
    r.dof = cells - 1;
    r.pValue = r.dof > 0 ? chiSquarePValue(r.statistic, r.dof) : 0.0;
    return r;
}

}  // namespace trazo
