// The half-space random-walk oracle and its H-function counterpart (halfspace_walk.h).
#include "support/halfspace_walk.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace trazo {

namespace {
constexpr int kMaxScatterings = 256;  // §6: a walk that scatters more than 256 times contributes 0
}

void halfspaceWalkReflectances(const double* albedos, int count, uint64_t walks, uint64_t seed, double* reflectances,
                               double* standardErrors, HalfspaceEntry entry) {
    std::mt19937_64 rng(seed);
    auto uniform = [](std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; };  // [0, 1), 53 bits
    // Only the depth matters in a half-space: each step needs the z of its direction and its length.
    std::vector<uint64_t> exits(kMaxScatterings + 1, 0);  // walks that leave after exactly k scatterings
    for (uint64_t w = 0; w < walks; ++w) {
        double z = 0.0;
        double dz = entry == HalfspaceEntry::Cosine ? -std::sqrt(1.0 - uniform(rng)) : -1.0;  // cos θ = √(1 − u)
        for (int k = 0;; ++k) {
            z += dz * -std::log(1.0 - uniform(rng));  // free path of mean 1
            if (z > 0.0) {  // (a first flight of length 0 stays at z = 0 and scatters: k ≥ 1 always)
                ++exits[k];
                break;
            }
            if (k == kMaxScatterings) break;  // the 257th scattering: contributes 0
            dz = 2.0 * uniform(rng) - 1.0;    // isotropic: cos θ uniform in [−1, 1]
        }
    }
    for (int a = 0; a < count; ++a) {
        double sum = 0.0, sum2 = 0.0;
        for (int k = 0; k <= kMaxScatterings; ++k) {
            const double v = std::pow(albedos[a], k);
            sum += double(exits[k]) * v;
            sum2 += double(exits[k]) * v * v;
        }
        const double n = double(walks), mean = sum / n;
        reflectances[a] = mean;
        if (standardErrors) standardErrors[a] = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1.0));
    }
}

double halfspaceWalkReflectance(double albedo, uint64_t walks, uint64_t seed, double* standardError) {
    double r, se;
    halfspaceWalkReflectances(&albedo, 1, walks, seed, &r, &se);
    if (standardError) *standardError = se;
    return r;
}

double halfspaceReflectanceChandrasekhar(double albedo, HalfspaceEntry entry) {
    const double root = std::sqrt(1.0 - albedo);
    if (root == 0.0) return 1.0;  // a conservative half-space returns every walk (H's moments stay finite)
    // 64-point Gauss–Legendre nodes on [0, 1] (Newton on P_64).
    constexpr int n = 64;
    double mu[n], weight[n];
    for (int i = 0; i < n; ++i) {
        double x = std::cos(3.14159265358979323846 * (i + 0.75) / (n + 0.5)), dp = 1.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = x;
            for (int j = 2; j <= n; ++j) {
                const double p2 = ((2.0 * j - 1.0) * x * p1 - (j - 1.0) * p0) / j;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (x * p1 - p0) / (x * x - 1.0);
            const double step = p1 / dp;
            x -= step;
            if (std::abs(step) < 1e-16) break;
        }
        mu[i] = 0.5 * (1.0 - x);
        weight[i] = 1.0 / ((1.0 - x * x) * dp * dp);
    }
    // 1/H(μ) = √(1 − α) + (α/2) ∫₀¹ μ′ H(μ′)/(μ + μ′) dμ′, iterated to a fixed point.
    std::vector<double> h(n, 1.0), next(n);
    auto hAt = [&](double m) {
        double s = 0.0;
        for (int j = 0; j < n; ++j) s += weight[j] * mu[j] * h[j] / (m + mu[j]);
        return 1.0 / (root + 0.5 * albedo * s);
    };
    for (int it = 0; it < 100000; ++it) {
        double change = 0.0;
        for (int i = 0; i < n; ++i) {
            next[i] = hAt(mu[i]);
            change = std::max(change, std::abs(next[i] - h[i]));
        }
        h.swap(next);
        if (change < 1e-15) break;
    }
    if (entry == HalfspaceEntry::Normal) return 1.0 - root * hAt(1.0);
    double firstMoment = 0.0;
    for (int i = 0; i < n; ++i) firstMoment += weight[i] * h[i] * mu[i];
    return 1.0 - 2.0 * root * firstMoment;
}

}  // namespace trazo
