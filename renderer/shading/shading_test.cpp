// Properties of the Oren–Nayar and Cook–Torrance terms of SPEC §5.
#include <gtest/gtest.h>

#include <random>

#include "shading/cook_torrance.h"
#include "shading/oren_nayar.h"

namespace trazo {
namespace {

Vec3 randomHemisphere(std::mt19937& rng, Vec3 n) {
    std::normal_distribution<float> g;
    for (;;) {
        Vec3 d(g(rng), g(rng), g(rng));
        if (lengthSquared(d) < 1e-6f) continue;
        d = normalize(d);
        if (dot(d, n) < 0.0f) d = -d;
        if (dot(d, n) > 1e-6f) return d;
    }
}

TEST(ShadingOrenNayar, RoughnessZeroIsExactlyLambertCosine) {
    std::mt19937 rng(1);
    const Vec3 n = normalize(Vec3(0.3f, 0.9f, -0.2f));
    for (int i = 0; i < 10000; ++i) {
        const Vec3 l = randomHemisphere(rng, n), v = randomHemisphere(rng, n);
        ASSERT_EQ(evalOrenNayar(n, l, v, 0.0f), fminf(dot(n, l), 1.0f));
    }
}

TEST(ShadingOrenNayar, WhiteSurfaceLitHeadOnIsOne) {
    const Vec3 n(0, 0, 1);
    EXPECT_EQ(evalOrenNayar(n, n, n, 0.0f), 1.0f);
}

TEST(ShadingOrenNayar, MatchesClosedFormForKnownAngles) {
    // θL = 60°, θV = 30°, φL = φV: cos(φL−φV) = 1, α = 60°, β = 30°.
    const float sigma = 0.5f, s2 = sigma * sigma;
    const float a = 1.0f - 0.5f * s2 / (s2 + 0.33f), b = 0.45f * s2 / (s2 + 0.09f);
    const float pi = 3.14159265358979f;
    const Vec3 n(0, 0, 1), l(sinf(pi / 3), 0, cosf(pi / 3)), v(sinf(pi / 6), 0, cosf(pi / 6));
    const float expected = cosf(pi / 3) * (a + b * sinf(pi / 3) * tanf(pi / 6));
    EXPECT_NEAR(evalOrenNayar(n, l, v, sigma), expected, 1e-6f);
    // Opposite azimuths: the B term vanishes.
    const Vec3 vOpposite(-sinf(pi / 6), 0, cosf(pi / 6));
    EXPECT_NEAR(evalOrenNayar(n, l, vOpposite, sigma), cosf(pi / 3) * a, 1e-6f);
}

TEST(ShadingOrenNayar, ReciprocalOnceTheCosineIsRemoved) {
    std::mt19937 rng(2);
    const Vec3 n(0, 1, 0);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 l = randomHemisphere(rng, n), v = randomHemisphere(rng, n);
        const float lv = evalOrenNayar(n, l, v, 0.7f) / dot(n, l);
        const float vl = evalOrenNayar(n, v, l, 0.7f) / dot(n, v);
        ASSERT_NEAR(lv, vl, 1e-4f * fmaxf(1.0f, lv));
    }
}

TEST(ShadingCookTorrance, MatchesClosedFormAtNormalIncidence) {
    // L = V = N: θH = 0, D = 1/(π m²), G = 1, CT = π·D/(4·1) = 1/(4 m²).
    const Vec3 n(0, 0, 1);
    for (float m : {0.1f, 0.3f, 0.9f}) EXPECT_NEAR(evalCookTorrance(n, n, n, m), 1.0f / (4.0f * m * m), 1e-3f / (m * m));
    // Roughness below 0.01 is clamped to 0.01.
    EXPECT_EQ(evalCookTorrance(n, n, n, 0.0f), evalCookTorrance(n, n, n, 0.01f));
}

TEST(ShadingProperties, NoNegativeOrNonFiniteValuesForRandomInputs) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 200000; ++i) {
        const Vec3 n = randomHemisphere(rng, Vec3(0, 0, 1));
        const Vec3 l = randomHemisphere(rng, n), v = randomHemisphere(rng, n);
        const float roughness = i % 10 == 0 ? 0.0f : u(rng) * 1.5f;
        const float on = evalOrenNayar(n, l, v, roughness);
        const float ct = evalCookTorrance(n, l, v, roughness);
        ASSERT_TRUE(std::isfinite(on) && on >= 0.0f) << on;
        ASSERT_TRUE(std::isfinite(ct) && ct >= 0.0f) << ct;
    }
}

}  // namespace
}  // namespace trazo
