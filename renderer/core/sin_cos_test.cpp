// sinCos against double precision, and its SIMD lanes against the scalar code bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/rng.h"
#include "core/sin_cos.h"
#include "integrator/packets/packet_lanes.h"

namespace trazo {
namespace {

// Units in the last place of a float at y's magnitude (a subnormal's for y = 0).
double ulpAt(double y) {
    const float f = std::fabs((float)y);
    return (double)std::nextafter(f, INFINITY) - (double)f;
}

struct Worst {
    double ulps = 0.0;
    void add(float got, double want) { ulps = std::fmax(ulps, std::fabs(got - want) / ulpAt(want)); }
};

// [0, 2π] at an even stride (the indirect directions' φ; θ is in [0, π/2]): within 2 ulp everywhere, zeros
// included (libm's sinf: 0.56). Beyond it, up to 2¹²·π/2: within 1e-7, and 2 ulp but near the zeros, where the
// reduction's error is some ulp of a tiny value.
TEST(SinCos, IsWithinTwoUlpAndOneTenMillionthOfTheTrueValues) {
    Worst sine, cosine, farSine, farCosine;
    auto check = [](float x, Worst& sines, Worst& cosines, bool all) {
        float s, c;
        sinCos(x, s, c);
        const double wantSin = std::sin((double)x), wantCos = std::cos((double)x);
        if (all || std::fabs(wantSin) >= 1.0 / 64) sines.add(s, wantSin);
        if (all || std::fabs(wantCos) >= 1.0 / 64) cosines.add(c, wantCos);
        EXPECT_LE(std::fabs(s - wantSin), 1e-7) << x;
        EXPECT_LE(std::fabs(c - wantCos), 1e-7) << x;
    };
    for (int i = 0; i <= 628318; ++i) check((float)i * 1e-5f, sine, cosine, true);
    for (uint32_t i = 0; i < 200000; ++i) check(bitsToUnitFloat(hashU32(i)) * 6400.0f, farSine, farCosine, false);
    EXPECT_LE(sine.ulps, 2.0);
    EXPECT_LE(cosine.ulps, 2.0);
    EXPECT_LE(farSine.ulps, 2.0);
    EXPECT_LE(farCosine.ulps, 2.0);
}

TEST(SinCos, IsExactAtZeroAndKeepsSignsInEveryQuadrant) {
    float s, c;
    sinCos(0.0f, s, c);
    EXPECT_EQ(s, 0.0f);
    EXPECT_EQ(c, 1.0f);
    for (int quadrant = 0; quadrant < 8; ++quadrant) {
        const float x = (quadrant + 0.5f) * 1.5707963f;  // the middle of each quadrant
        sinCos(x, s, c);
        EXPECT_EQ(s > 0.0f, std::sin((double)x) > 0.0) << x;
        EXPECT_EQ(c > 0.0f, std::cos((double)x) > 0.0) << x;
        EXPECT_NEAR(s * s + c * c, 1.0f, 3e-7f) << x;
    }
}

TEST(SinCos, LanesAreTheScalarCodeBitForBit) {
    using namespace packet_detail;
    for (uint32_t i = 0; i < 100000; i += kLanes) {
        alignas(64) float x[kLanes], s[kLanes], c[kLanes];
        for (int k = 0; k < kLanes; ++k) x[k] = bitsToUnitFloat(hashU32(i + k)) * (i < 50000 ? 6.2831853f : 6400.0f);
        LaneF ls, lc;
        sinCosOf<LaneOps>(load(x), ls, lc);
        std::memcpy(s, &ls, sizeof ls);
        std::memcpy(c, &lc, sizeof lc);
        for (int k = 0; k < kLanes; ++k) {
            float want[2];
            sinCos(x[k], want[0], want[1]);
            ASSERT_EQ(std::memcmp(&s[k], &want[0], 4), 0) << "sin " << x[k];
            ASSERT_EQ(std::memcmp(&c[k], &want[1], 4), 0) << "cos " << x[k];
        }
    }
}

}  // namespace
}  // namespace trazo
