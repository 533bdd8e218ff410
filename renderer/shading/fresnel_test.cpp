// dielectricFresnel against closed forms, reciprocity and an independent double-precision evaluation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "shading/fresnel.h"

namespace trazo {
namespace {

// The textbook form in double (rs, rp from cos θt = √(1 − (n1/n2)² sin²θi)): the reference.
double fresnelReference(double cosI, double n1, double n2) {
    const double sin2T = (n1 / n2) * (n1 / n2) * (1.0 - cosI * cosI);
    if (sin2T >= 1.0) return 1.0;
    const double cosT = std::sqrt(1.0 - sin2T);
    const double rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
    const double rp = (n2 * cosI - n1 * cosT) / (n2 * cosI + n1 * cosT);
    return 0.5 * (rs * rs + rp * rp);
}

// A second, algebraically different form in double (the "g-form" of Cook & Torrance / Walter et al.):
// g = √(k² − 1 + c²), F = ½((g−c)/(g+c))² (1 + ((c(g+c) − 1)/(c(g−c) + 1))²). Checks the reference itself.
double fresnelGForm(double cosI, double n1, double n2) {
    const double k = n2 / n1, g2 = k * k - 1.0 + cosI * cosI;
    if (g2 <= 0.0) return 1.0;
    const double g = std::sqrt(g2), a = (g - cosI) / (g + cosI);
    const double b = (cosI * (g + cosI) - 1.0) / (cosI * (g - cosI) + 1.0);
    return 0.5 * a * a * (1.0 + b * b);
}

// Schlick's approximation, the usual mistake: the grid comparison must reject it.
float fresnelSchlick(float cosI, float n1, float n2) {
    const float r0 = (n1 - n2) / (n1 + n2);
    return r0 * r0 + (1.0f - r0 * r0) * powf(1.0f - cosI, 5.0f);
}

// The textbook form in float: the backward-error check must reject it near the critical angle.
float fresnelNaiveFloat(float cosI, float n1, float n2) {
    const float eta = n1 / n2, sin2T = eta * eta * (1.0f - cosI * cosI);
    if (sin2T >= 1.0f) return 1.0f;
    const float cosT = sqrtf(1.0f - sin2T);
    const float rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
    const float rp = (n2 * cosI - n1 * cosT) / (n2 * cosI + n1 * cosT);
    return 0.5f * (rs * rs + rp * rp);
}

double degrees(double d) { return d * 3.14159265358979323846 / 180.0; }

// Indices on both sides of every pair below: air, nearly air, water, glass, flint, diamond, silicon-ish.
const std::vector<float> kIndices = {1.0f, 1.0001f, 1.2f, 1.333f, 1.5f, 1.7f, 2.42f, 3.5f};

// Whether F is the exact (double) reflectance of an incidence cosine within `ulps` float ulps of cosI, up to
// `slack` in F: the mixed forward–backward criterion. Near the critical angle F has an infinite derivative in
// cos θi, so a forward tolerance alone would be either loose everywhere or unmeetable there.
bool backwardStable(float f, float cosI, float n1, float n2, int ulps, double slack) {
    const double step = ulps * 5.960464477539063e-8;  // 2^-24: half an ulp of [0.5, 1), conservative below
    const double lo = fresnelReference(cosI * (1.0 - step), n1, n2);
    const double hi = fresnelReference(std::min(1.0, cosI * (1.0 + step)), n1, n2);
    return f >= std::min(lo, hi) - slack && f <= std::max(lo, hi) + slack;
}

// The cosines of the grid: 0° to 90° every 0.05°, plus every index pair's critical angle ±200 floats.
std::vector<float> gridCosines(float n1, float n2) {
    std::vector<float> c;
    for (int i = 0; i <= 1800; ++i) c.push_back(float(std::cos(degrees(i * 0.05))));
    if (n1 > n2) {
        float critical = float(std::sqrt(1.0 - double(n2) * n2 / (double(n1) * n1)));
        for (int i = 0; i < 200; ++i) critical = std::nextafter(critical, 0.0f);
        for (int i = 0; i < 400; ++i, critical = std::nextafter(critical, 2.0f)) c.push_back(critical);
    }
    return c;
}

TEST(DielectricFresnel, ReferenceFormsAgree) {
    for (float n1 : kIndices)
        for (float n2 : kIndices)
            for (int i = 0; i <= 900; ++i) {
                const double c = std::cos(degrees(i * 0.1));
                if (n1 == n2 && i == 900) continue;  // 0/0 in both forms: no interface, at grazing
                ASSERT_NEAR(fresnelReference(c, n1, n2), fresnelGForm(c, n1, n2), 1e-12) << n1 << " " << n2 << " " << c;
            }
}

TEST(DielectricFresnel, NormalIncidence) {
    EXPECT_NEAR(dielectricFresnel(1.0f, 1.0f, 1.5f), 0.04f, 1e-8f);
    EXPECT_NEAR(dielectricFresnel(1.0f, 1.5f, 1.0f), 0.04f, 1e-8f);  // the same from inside
    const float f = dielectricFresnel(1.0f, 1.0f, 1.5f);
    EXPECT_NEAR((1.0f - f) / (1.0f + f), 0.923077f, 1e-6f);  // §6's slab check
    for (float n1 : kIndices)
        for (float n2 : kIndices) {
            const double r = (double(n1) - n2) / (double(n1) + n2);
            EXPECT_NEAR(dielectricFresnel(1.0f, n1, n2), r * r, 1e-7) << n1 << " → " << n2;
        }
}

// Spot values from Mitsuba 3's test_fresnel.py and test_dielectric.py (future-work-anchors.md §5.2).
TEST(DielectricFresnel, MitsubaSpotValues) {
    EXPECT_NEAR(dielectricFresnel(float(std::cos(degrees(45))), 1.0f, 1.5f), 0.050240, 1e-6);
    EXPECT_NEAR(dielectricFresnel(float(std::cos(degrees(80))), 1.0f, 1.5f), 0.387704354691473, 1e-6);
    EXPECT_NEAR(dielectricFresnel(float(std::cos(degrees(10))), 1.5f, 1.0f), 0.040083, 1e-6);
    EXPECT_EQ(dielectricFresnel(float(std::cos(degrees(45))), 1.5f, 1.0f), 1.0f);  // TIR
}

// At Brewster's angle tan θB = n2/n1 the p-wave vanishes and F = rs²/2 = ½((n1² − n2²)/(n1² + n2²))².
TEST(DielectricFresnel, BrewsterAngleLeavesOnlyTheSWave) {
    for (float n1 : kIndices)
        for (float n2 : kIndices) {
            if (n1 == n2) continue;
            const double a = double(n1) * n1, b = double(n2) * n2;
            const double cosB = double(n1) / std::sqrt(a + b);
            const double rs = (a - b) / (a + b);
            EXPECT_NEAR(fresnelReference(cosB, n1, n2), 0.5 * rs * rs, 1e-14);
            // 5e-7: F's slope at θB times the rounding of cos θB to a float, plus a few ulps of F.
            EXPECT_NEAR(dielectricFresnel(float(cosB), n1, n2), 0.5 * rs * rs, 5e-7) << n1 << " → " << n2;
        }
    // 1 → 1.5: θB = 56.31° (Mitsuba's value) and F = 0.0739645.
    EXPECT_NEAR(std::atan(1.5) * 180.0 / 3.14159265358979323846, 56.31, 0.005);
    EXPECT_NEAR(dielectricFresnel(float(1.0 / std::sqrt(3.25)), 1.0f, 1.5f), 0.0739645, 1e-7);
}

TEST(DielectricFresnel, GrazingIncidenceReflectsEverything) {
    for (float n1 : kIndices)
        for (float n2 : kIndices) {
            if (n1 == n2) continue;
            EXPECT_EQ(dielectricFresnel(0.0f, n1, n2), 1.0f) << n1 << " → " << n2;
            EXPECT_EQ(dielectricFresnel(-0.0f, n1, n2), 1.0f);
            EXPECT_NEAR(dielectricFresnel(1e-6f, n1, n2), fresnelReference(1e-6f, n1, n2), 1e-6);
        }
    // Approaching grazing from outside glass, F rises to 1 (and passes 0.9 by 89.5°); near normal incidence
    // F is flat, so consecutive values may tie or dip by an ulp.
    float previous = 0.0f;
    for (int i = 0; i <= 900; ++i) {
        const float f = dielectricFresnel(float(std::cos(degrees(i * 0.1))), 1.0f, 1.5f);
        EXPECT_GE(f, previous - 1e-8f) << i * 0.1 << "°";
        previous = f;
    }
    EXPECT_GT(dielectricFresnel(float(std::cos(degrees(89.5))), 1.0f, 1.5f), 0.9f);
}

TEST(DielectricFresnel, TotalInternalReflectionAboveTheCriticalAngle) {
    for (float n1 : kIndices)
        for (float n2 : kIndices) {
            if (n1 <= n2) continue;
            const double cosC = std::sqrt(1.0 - double(n2) * n2 / (double(n1) * n1));
            for (double t : {0.0, 0.25, 0.5, 0.9, 0.999, 0.99999})  // cos θi below cos θc: beyond the angle
                EXPECT_EQ(dielectricFresnel(float(cosC * t), n1, n2), 1.0f) << n1 << " → " << n2 << " " << t;
            // Just inside the critical angle F < 1 but close: the two branches join.
            const float justInside = float(cosC * (1.0 + 1e-4));
            EXPECT_LT(dielectricFresnel(justInside, n1, n2), 1.0f);
            EXPECT_NEAR(dielectricFresnel(justInside, n1, n2), fresnelReference(justInside, n1, n2), 1e-4);
        }
    // Glass → air: θc = 41.81°.
    EXPECT_NEAR(std::asin(1.0 / 1.5) * 180.0 / 3.14159265358979323846, 41.81, 0.005);
    EXPECT_LT(dielectricFresnel(float(std::cos(degrees(41.7))), 1.5f, 1.0f), 1.0f);
    EXPECT_EQ(dielectricFresnel(float(std::cos(degrees(41.9))), 1.5f, 1.0f), 1.0f);
}

// F(θi; n1, n2) = F(θt; n2, n1) with sin θt = (n1/n2) sin θi: the same interface seen from the other side.
// Tolerance: 4 ulps of F, plus what rounding each cosine to a float moves F by (|dF/dcos|·cos·2⁻²³, the
// slope by central difference in double), which grows without bound as θt nears the critical angle.
TEST(DielectricFresnel, Reciprocity) {
    auto roundingEffect = [](double c, double n1, double n2) {
        const double h = 1e-7 * c;
        return std::abs(fresnelReference(c + h, n1, n2) - fresnelReference(c - h, n1, n2)) / (2.0 * h) * c * 1.2e-7;
    };
    for (float n1 : kIndices)
        for (float n2 : kIndices) {
            if (n1 >= n2) continue;  // from the lower index every angle refracts
            for (int i = 0; i <= 890; ++i) {
                const double thetaI = degrees(i * 0.1);
                const double cosT = std::cos(std::asin(double(n1) / n2 * std::sin(thetaI)));
                const float there = dielectricFresnel(float(std::cos(thetaI)), n1, n2);
                const float back = dielectricFresnel(float(cosT), n2, n1);
                const double tolerance = 5e-7 + roundingEffect(std::cos(thetaI), n1, n2) + roundingEffect(cosT, n2, n1);
                EXPECT_NEAR(there, back, tolerance) << n1 << " ↔ " << n2 << " at " << i * 0.1 << "°";
                EXPECT_NEAR(fresnelReference(std::cos(thetaI), n1, n2), fresnelReference(cosT, n2, n1), 1e-12);
            }
        }
}

// Every grid point: forward error ≤ 2e-6 away from the critical angle (c² = cos²θi + k² − 1 ≥ 1e-2), and
// everywhere the exact F of a cosine within 1 ulp of the argument, up to 5e-7 (4 ulps of 1) in F.
TEST(DielectricFresnel, AgreesWithDoublePrecisionOverAGrid) {
    int points = 0;
    double worstFar = 0.0;
    for (float n1 : kIndices)
        for (float n2 : kIndices) {
            if (n1 == n2) continue;
            for (float c : gridCosines(n1, n2)) {
                const float f = dielectricFresnel(c, n1, n2);
                ASSERT_TRUE(f >= 0.0f && f <= 1.0f) << f;
                ASSERT_TRUE(backwardStable(f, c, n1, n2, 1, 5e-7))
                    << n1 << " → " << n2 << " cos " << c << ": " << f << " vs " << fresnelReference(c, n1, n2);
                const double k = double(n2) / n1;
                if (double(c) * c + k * k - 1.0 >= 1e-2) worstFar = std::max(worstFar, std::abs(f - fresnelReference(c, n1, n2)));
                ++points;
            }
        }
    EXPECT_LT(worstFar, 2e-6);
    EXPECT_GT(points, 90000);
}

// The same criteria reject the textbook float formula (critical angle) and Schlick (everywhere): the grid is
// tight enough to catch both.
TEST(DielectricFresnel, GridRejectsTheNaiveFormAndSchlick) {
    int naiveFailures = 0, schlickFailures = 0;
    for (float n1 : kIndices)
        for (float n2 : kIndices) {
            if (n1 == n2) continue;
            for (float c : gridCosines(n1, n2)) {
                naiveFailures += !backwardStable(fresnelNaiveFloat(c, n1, n2), c, n1, n2, 1, 5e-7);
                schlickFailures += !backwardStable(fresnelSchlick(c, n1, n2), c, n1, n2, 1, 5e-7);
            }
        }
    EXPECT_GT(naiveFailures, 100);
    EXPECT_GT(schlickFailures, 10000);
    // Schlick's worst case named in the anchors: −16% at 45° from outside glass.
    const float c45 = float(std::cos(degrees(45)));
    EXPECT_NEAR(fresnelSchlick(c45, 1.0f, 1.5f) / dielectricFresnel(c45, 1.0f, 1.5f) - 1.0f, -0.163f, 0.002f);
}

TEST(DielectricFresnel, EqualIndicesReflectNothing) {
    for (float n : {0.5f, 1.0f, 1.5f, 3.5f})
        for (int i = 0; i <= 100; ++i) EXPECT_EQ(dielectricFresnel(i / 100.0f, n, n), 0.0f);
}

TEST(DielectricFresnel, AlwaysFiniteAndWithinZeroOne) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> logIndex(-3.0f, 3.0f), cosine(-1.5f, 1.5f);
    for (int i = 0; i < 200000; ++i) {
        const float n1 = std::pow(10.0f, logIndex(rng)), n2 = std::pow(10.0f, logIndex(rng)), c = cosine(rng);
        const float f = dielectricFresnel(c, n1, n2);
        ASSERT_TRUE(f >= 0.0f && f <= 1.0f) << c << " " << n1 << " " << n2 << " → " << f;
        EXPECT_EQ(f, dielectricFresnel(-c, n1, n2));  // only |cos θi| counts
    }
    EXPECT_EQ(dielectricFresnel(1.5f, 1.0f, 1.5f), dielectricFresnel(1.0f, 1.0f, 1.5f));  // cos beyond 1 counts as 1
}

}  // namespace
}  // namespace trazo
