// The glossy cones' sampler (sampleCone: reflection about the mirror direction, SPEC §6's transmission about
// Snell's): over passes and pixels its directions are θ uniform in [0, half-angle) and φ uniform about the
// axis, checked by Pearson's χ² at the anchors note's settings (10⁶ samples, α = 0.01, Šidák over the tests),
// through the strata and the counter-based generator the renderer draws them with.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "integrator/thesis/thesis_integrator.h"
#include "support/chi_square.h"

namespace trazo {
namespace {

constexpr int kThetaBins = 20, kPhiBins = 40;
constexpr int kChiSquareTestsHere = 4;
const double kLevel = sidakLevel(kChiSquareSignificance, kChiSquareTestsHere);

// Histogram of (θ/half-angle, φ) of sampleCone's directions: one per (pixel, pass), the pass cycling the
// cone's 2q² strata. `thetaOf` maps the true polar angle to the one binned (the identity, or a wrong model).
ChiSquareResult coneChiSquare(Vec3 axis, float halfAngle, uint32_t quality, double (*thetaOf)(double, double)) {
    std::vector<double> observed(kThetaBins * kPhiBins, 0.0);
    const Vec3 t1 = anyOrthonormal(axis), t2 = cross(axis, t1);
    const uint32_t passes = 2 * quality * quality * 4;
    const uint32_t pixels = (kChiSquareSamples + passes - 1) / passes;
    int samples = 0;
    for (uint32_t pixel = 0; pixel < pixels; ++pixel) {
        for (uint32_t pass = 0; pass < passes && samples < kChiSquareSamples; ++pass, ++samples) {
            SampleStream rng(11u, pixel, pass);
            const StrataKey strata{5u, pixel, pass, kSampleTreeRoot};
            const Vec3 d = sampleCone(axis, halfAngle, quality, kGridGlossyTransmission, strata, rng);
            const double cosTheta = std::min(1.0, std::max(-1.0, double(dot(d, axis))));
            const double theta = thetaOf(std::acos(cosTheta), halfAngle);
            const double phi = std::atan2(double(dot(d, t2)), double(dot(d, t1))) + M_PI;
            const int i = std::min(kThetaBins - 1, int(theta / halfAngle * kThetaBins));
            const int j = std::min(kPhiBins - 1, int(phi / (2 * M_PI) * kPhiBins));
            observed[size_t(i) * kPhiBins + j] += 1.0;
        }
    }
    const std::vector<double> expected(observed.size(), double(samples) / double(observed.size()));
    return chiSquareTest(observed, expected);
}

double sameTheta(double theta, double) { return theta; }
// A sampler uniform in solid angle over the cone would give θ with cos θ uniform: binned as uniform in θ it
// crowds the rim. Mapping the true θ through the uniform-solid-angle CDF turns the right sampler into that
// wrong one, which the test must reject.
double solidAngleTheta(double theta, double halfAngle) {
    return halfAngle * (1.0 - std::cos(theta)) / (1.0 - std::cos(halfAngle));
}

TEST(GlossyCone, ThetaAndPhiAreUniformOverThePassesStrata) {
    const Vec3 axes[] = {Vec3(0, 0, 1), normalize(Vec3(0.3f, -0.5f, 0.8f)), normalize(Vec3(-1e-4f, 1, 0))};
    const float halfAngles[] = {0.1745329f, 0.7853982f, 1.5707964f};  // 10°, 45°, 90° (RefractionAngle 180)
    for (int k = 0; k < 3; ++k) {
        const ChiSquareResult r = coneChiSquare(axes[k], halfAngles[k], 3, sameTheta);
        EXPECT_TRUE(r.accepts(kLevel)) << "axis " << k << ": χ² " << r.statistic << " dof " << r.dof << " p "
                                       << r.pValue << " " << r.failure;
    }
}

TEST(GlossyCone, ChiSquareRejectsAConeUniformInSolidAngle) {
    const ChiSquareResult r = coneChiSquare(Vec3(0, 0, 1), 0.7853982f, 3, solidAngleTheta);
    EXPECT_FALSE(r.accepts(kLevel)) << "χ² " << r.statistic << " dof " << r.dof << " p " << r.pValue;
}

}  // namespace
}  // namespace trazo
