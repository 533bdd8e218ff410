// The random walk's samplers against their pdfs: χ² on the sphere (Mitsuba's (φ, cos θ) domain at pbrt's
// 10⁶ samples, α = 0.01 Šidák over the file's χ² tests), the free path's moments, and wrong samplers rejected.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/rng.h"
#include "integrator/random_walk.h"
#include "support/chi_square.h"

namespace trazo {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The χ² tests of this file that must pass together: isotropic, cosine about six normals, the free path.
constexpr int kChiSquareTestsHere = 8;
const double kLevel = sidakLevel(kChiSquareSignificance, kChiSquareTestsHere);

float unitFloat(std::mt19937_64& rng) { return bitsToUnitFloat(uint32_t(rng() >> 32)); }

// An orthonormal frame about n built in double by Gram–Schmidt, independent of the sampler's anyOrthonormal.
struct Frame {
    double n[3], t[3], b[3];
    explicit Frame(Vec3 nf) : n{nf.x, nf.y, nf.z} {
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (double& v : n) v /= len;
        double a[3] = {1, 0, 0};
        if (std::abs(n[0]) > 0.6) a[0] = 0, a[1] = 1;
        const double d = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
        for (int i = 0; i < 3; ++i) t[i] = a[i] - d * n[i];
        const double tl = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        for (double& v : t) v /= tl;
        b[0] = n[1] * t[2] - n[2] * t[1];
        b[1] = n[2] * t[0] - n[0] * t[2];
        b[2] = n[0] * t[1] - n[1] * t[0];
    }
    // (cos θ, φ ∈ [−π, π]) of a direction in this frame.
    void local(Vec3 d, double& cosTheta, double& phi) const {
        const double x = d.x * t[0] + d.y * t[1] + d.z * t[2], y = d.x * b[0] + d.y * b[1] + d.z * b[2];
        cosTheta = d.x * n[0] + d.y * n[1] + d.z * n[2];
        phi = std::atan2(y, x);
    }
};

// Mitsuba's SphericalDomain: 50 φ columns × 101 cos θ rows.
constexpr int kPhi = kChiSquarePhiBins, kCos = kChiSquareResolution;

int sphericalCell(double cosTheta, double phi) {
    const int i = std::clamp(int((cosTheta + 1.0) * 0.5 * kCos), 0, kCos - 1);
    const int j = std::clamp(int((phi + kPi) / (2.0 * kPi) * kPhi), 0, kPhi - 1);
    return i * kPhi + j;
}

// Expected counts of a pdf that depends on cos θ only, from its cumulative P(cos θ ≤ c): exact per cell.
template <class Cdf>
std::vector<double> expectedSphericalCounts(Cdf cdfOfCos) {
    std::vector<double> e(kCos * kPhi);
    for (int i = 0; i < kCos; ++i) {
        const double p = cdfOfCos(-1.0 + 2.0 * (i + 1) / kCos) - cdfOfCos(-1.0 + 2.0 * i / kCos);
        for (int j = 0; j < kPhi; ++j) e[i * kPhi + j] = kChiSquareSamples * p / kPhi;
    }
    return e;
}
double isotropicCdf(double c) { return 0.5 * (c + 1.0); }
double cosineCdf(double c) { return c <= 0.0 ? 0.0 : c * c; }  // ∫ cos θ/π dω over cos θ ∈ [0, c]

template <class Sampler>
ChiSquareResult sphericalChiSquare(Sampler sample, const Frame& frame, std::vector<double> expected, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<double> observed(kCos * kPhi, 0.0);
    for (int k = 0; k < kChiSquareSamples; ++k) {
        const float u1 = unitFloat(rng), u2 = unitFloat(rng);
        double c, phi;
        frame.local(sample(u1, u2), c, phi);
        observed[sphericalCell(c, phi)] += 1.0;
    }
    return chiSquareTest(observed, expected);
}

const std::vector<Vec3> kNormals = {Vec3(0, 0, 1),  Vec3(0, 0, -1), Vec3(1, 0, 0), normalize(Vec3(0.3f, -0.5f, 0.8f)),
                                    normalize(Vec3(1e-4f, 0, -1)), normalize(Vec3(-0.7f, 0.7f, 0.1f))};

TEST(RandomWalk, IsotropicIsUniformOnTheSphere) {
    const ChiSquareResult r = sphericalChiSquare(sampleIsotropic, Frame(Vec3(0, 0, 1)), expectedSphericalCounts(isotropicCdf), 1);
    EXPECT_TRUE(r.accepts(kLevel)) << "χ² " << r.statistic << " dof " << r.dof << " p " << r.pValue;
    EXPECT_EQ(r.dof, kCos * kPhi - 1);  // 198 samples a cell: nothing pooled
}

TEST(RandomWalk, CosineAboutNormalHasPdfCosOverPi) {
    const std::vector<double> expected = expectedSphericalCounts(cosineCdf);
    for (size_t k = 0; k < kNormals.size(); ++k) {
        const Vec3 n = kNormals[k];
        const ChiSquareResult r =
            sphericalChiSquare([&](float u1, float u2) { return sampleCosineAbout(n, u1, u2); }, Frame(n), expected, 10 + k);
        EXPECT_TRUE(r.accepts(kLevel)) << "n " << n.x << " " << n.y << " " << n.z << ": χ² " << r.statistic << " dof "
                                       << r.dof << " p " << r.pValue << " " << r.failure;
    }
}

// Wrong samplers the same test must reject: θ uniform in [0, π] (the poles crowded), a uniform hemisphere
// (cos θ = u1) posing as the cosine lobe, and the cosine lobe about a normal other than the one asked.
TEST(RandomWalk, ChiSquareRejectsWrongDirections) {
    auto uniformTheta = [](float u1, float u2) {
        const float theta = float(kPi) * u1, phi = 2.0f * float(kPi) * u2;
        return Vec3(sinf(theta) * cosf(phi), sinf(theta) * sinf(phi), cosf(theta));
    };
    const ChiSquareResult a = sphericalChiSquare(uniformTheta, Frame(Vec3(0, 0, 1)), expectedSphericalCounts(isotropicCdf), 2);
    EXPECT_FALSE(a.accepts(kLevel)) << a.pValue;
    const Vec3 n = kNormals[3];
    auto uniformHemisphere = [&](float u1, float u2) {
        const float c = 1.0f - u1, s = sqrtf(1.0f - c * c), phi = 2.0f * float(kPi) * u2;
        const Vec3 t1 = anyOrthonormal(n), t2 = cross(n, t1);
        return t1 * (s * cosf(phi)) + t2 * (s * sinf(phi)) + n * c;
    };
    const ChiSquareResult b = sphericalChiSquare(uniformHemisphere, Frame(n), expectedSphericalCounts(cosineCdf), 3);
    EXPECT_FALSE(b.accepts(kLevel)) << b.pValue;
    // About a normal 2° off. (Measured power, 10 seeds each: a tilt of 0.57° is rejected 10 times in 10.)
    const Vec3 tilted = normalize(n + anyOrthonormal(n) * 0.035f);
    const ChiSquareResult c = sphericalChiSquare([&](float u1, float u2) { return sampleCosineAbout(tilted, u1, u2); }, Frame(n),
                                                 expectedSphericalCounts(cosineCdf), 4);
    EXPECT_FALSE(c.accepts(kLevel)) << c.pValue;
}

TEST(RandomWalk, DirectionsAreUnitAndCosineOnesFaceTheNormal) {
    std::mt19937_64 rng(21);
    for (int k = 0; k < 100000; ++k) {
        const float u1 = unitFloat(rng), u2 = unitFloat(rng);
        ASSERT_NEAR(length(sampleIsotropic(u1, u2)), 1.0f, 2e-6f);
        for (Vec3 n : kNormals) {
            const Vec3 d = sampleCosineAbout(n, u1, u2);
            ASSERT_NEAR(length(d), 1.0f, 2e-6f);
            ASSERT_GT(dot(d, n), 0.0f);
        }
    }
    const float below1 = 0.99999994f;
    for (float u1 : {0.0f, below1})
        for (float u2 : {0.0f, 0.5f, below1}) {
            EXPECT_NEAR(length(sampleIsotropic(u1, u2)), 1.0f, 2e-6f);
            for (Vec3 n : kNormals) EXPECT_GT(dot(sampleCosineAbout(n, u1, u2), n), 0.0f);
        }
    EXPECT_EQ(sampleIsotropic(0.0f, 0.3f).z, 1.0f);
    EXPECT_EQ(sampleIsotropic(0.0f, 0.3f).x, 0.0f);
}

// The free path: 101 bins over [0, 8d) and one beyond, expected counts from the exponential's cdf exactly.
template <class Sampler>
ChiSquareResult freePathChiSquare(Sampler sample, float d, uint64_t seed) {
    constexpr int bins = kChiSquareResolution;
    const double width = 8.0 * d / bins;
    std::vector<double> observed(bins + 1, 0.0), expected(bins + 1);
    for (int i = 0; i < bins; ++i) expected[i] = kChiSquareSamples * (std::exp(-i * width / d) - std::exp(-(i + 1) * width / d));
    expected[bins] = kChiSquareSamples * std::exp(-8.0);
    std::mt19937_64 rng(seed);
    for (int k = 0; k < kChiSquareSamples; ++k) observed[std::min(int(sample(d, unitFloat(rng)) / width), bins)] += 1.0;
    return chiSquareTest(observed, expected);
}

TEST(RandomWalk, FreePathIsExponential) {
    const ChiSquareResult r = freePathChiSquare(sampleFreePath, 0.37f, 5);
    EXPECT_TRUE(r.accepts(kLevel)) << "χ² " << r.statistic << " dof " << r.dof << " p " << r.pValue;
    // A free path 2% too long fails (χ² ≈ 500 on 101 dof). Measured power, 10 seeds: 1% too long 10/10, 0.5% 4/10.
    const ChiSquareResult wrong = freePathChiSquare([](float d, float u) { return sampleFreePath(1.02f * d, u); }, 0.37f, 6);
    EXPECT_FALSE(wrong.accepts(kLevel)) << wrong.pValue;
}

// Mean d and variance d², each within 4 standard errors (the variance of (s − d)² is 8d⁴ for an exponential).
TEST(RandomWalk, FreePathMeanAndVariance) {
    std::mt19937_64 rng(8);
    for (float d : {0.01f, 1.0f, 250.0f}) {
        constexpr int n = 1000000;
        double sum = 0.0, sum2 = 0.0;
        for (int k = 0; k < n; ++k) {
            const double s = sampleFreePath(d, unitFloat(rng));
            sum += s;
            sum2 += (s - d) * (s - d);
        }
        const double mean = sum / n, variance = sum2 / n;
        EXPECT_NEAR(mean, d, 4.0 * d / std::sqrt(double(n))) << d;
        EXPECT_NEAR(variance, double(d) * d, 4.0 * std::sqrt(8.0) * double(d) * d / std::sqrt(double(n))) << d;
    }
}

// Every u the renderer can draw (bitsToUnitFloat's 2²⁴ values) gives a finite path ≥ 0, non-decreasing in u;
// u = 0 gives 0, and even u = 1 stays finite.
TEST(RandomWalk, FreePathIsFiniteForEveryUniform) {
    float previous = 0.0f;
    for (uint32_t i = 0; i < (1u << 24); ++i) {
        const float s = sampleFreePath(1.0f, bitsToUnitFloat(i << 8));
        if (!(std::isfinite(s) && s >= previous)) FAIL() << "u " << i << " / 2^24 → " << s;
        previous = s;
    }
    EXPECT_EQ(sampleFreePath(2.0f, 0.0f), 0.0f);
    EXPECT_NEAR(previous, 24.0 * std::log(2.0), 1e-5);  // −ln(2⁻²⁴)
    EXPECT_TRUE(std::isfinite(sampleFreePath(1.0f, 1.0f)));
    EXPECT_NEAR(sampleFreePath(3.0f, 1e-30f), 3e-30f, 1e-36f);  // log1p keeps tiny u exact
}

}  // namespace
}  // namespace trazo
