// SPEC §6's subsurface check values from the independent half-space oracle (support/halfspace_walk.h):
// R(0.5) = 0.147, R(0.8) = 0.342, R(1) = 0.919, and the oracle against Chandrasekhar's H-function.
#include <gtest/gtest.h>

#include <cmath>

#include "support/halfspace_walk.h"

namespace trazo {
namespace {

// 2·10⁶ walks (~2 s on one core of the 2-core build machine): standard errors ≈ 1.4e-4, 2.3e-4, 1.9e-4 for α = 0.5, 0.8, 1.
constexpr uint64_t kWalks = 2000000;
constexpr double kAlbedos[3] = {0.5, 0.8, 1.0};
constexpr double kSpec[3] = {0.147, 0.342, 0.919};

struct Estimates {
    double r[3], se[3];
};

const Estimates& specWalks() {
    static const Estimates e = [] {
        Estimates x{};
        halfspaceWalkReflectances(kAlbedos, 3, kWalks, 2024, x.r, x.se);
        return x;
    }();
    return e;
}

// §6 prints three decimals, so the true value lies within ±0.0005 of each: the estimate must be within that
// plus 4 standard errors, and (the brief's bound) within ±0.001.
TEST(HalfspaceWalk, ReproducesTheSpecValues) {
    const Estimates& e = specWalks();
    for (int i = 0; i < 3; ++i) {
        EXPECT_LT(e.se[i], 2.5e-4) << kAlbedos[i];
        EXPECT_LE(std::abs(e.r[i] - kSpec[i]), 0.0005 + 4.0 * e.se[i]) << "R(" << kAlbedos[i] << ") = " << e.r[i] << " ± " << e.se[i];
        EXPECT_LE(std::abs(e.r[i] - kSpec[i]), 0.001) << "R(" << kAlbedos[i] << ") = " << e.r[i];
    }
}

// Without the cap the half-space reflectance has a closed form in the H-function; for α ≤ 0.8 the cap is
// immaterial (0.8²⁵⁷ ≈ 1e-25), so the walks must match it to their own noise. Its values also show that §6's
// 0.147 and 0.342 are the correct roundings (0.146544, 0.341867). At α = 1 every walk leaves eventually
// (R = 1): the cap at 256 scatterings is what leaves 0.919.
TEST(HalfspaceWalk, AgreesWithChandrasekhar) {
    const Estimates& e = specWalks();
    const double h05 = halfspaceReflectanceChandrasekhar(0.5), h08 = halfspaceReflectanceChandrasekhar(0.8);
    EXPECT_NEAR(h05, 0.146544, 1e-6);
    EXPECT_NEAR(h08, 0.341867, 1e-6);
    EXPECT_NEAR(e.r[0], h05, 4.0 * e.se[0]);
    EXPECT_NEAR(e.r[1], h08, 4.0 * e.se[1]);
    EXPECT_EQ(std::round(h05 * 1000.0), 147.0);
    EXPECT_EQ(std::round(h08 * 1000.0), 342.0);
    EXPECT_NEAR(halfspaceReflectanceChandrasekhar(1.0), 1.0, 1e-12);
    EXPECT_LT(e.r[2], 0.93);
    EXPECT_NEAR(halfspaceReflectanceChandrasekhar(1e-9), 0.0, 1e-9);  // nothing scatters back
}

// Readings §6 rules out give other numbers, and the same criteria reject them: walks entering straight down
// (a misreading of "lit head-on"), and weighting α^(k+1) (absorbing on entry too).
TEST(HalfspaceWalk, OtherReadingsAreRejected) {
    double r[3], se[3];
    halfspaceWalkReflectances(kAlbedos, 3, 200000, 99, r, se, HalfspaceEntry::Normal);
    for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(r[i], halfspaceReflectanceChandrasekhar(kAlbedos[i], HalfspaceEntry::Normal), 4.0 * se[i]);
        EXPECT_GT(std::abs(r[i] - kSpec[i]), 0.0005 + 4.0 * se[i]) << "normal entry R(" << kAlbedos[i] << ") = " << r[i];
    }
    const Estimates& e = specWalks();
    for (int i = 0; i < 2; ++i) EXPECT_GT(std::abs(kAlbedos[i] * e.r[i] - kSpec[i]), 0.001);
}

TEST(HalfspaceWalk, OneAlbedoIsTheBatchsFirst) {
    double se1 = 0.0, r[3], se[3];
    const double r1 = halfspaceWalkReflectance(0.8, 20000, 5, &se1);
    halfspaceWalkReflectances(kAlbedos + 1, 2, 20000, 5, r, se);
    EXPECT_EQ(r1, r[0]);
    EXPECT_EQ(se1, se[0]);
    EXPECT_GT(se1, 0.0);
    EXPECT_EQ(halfspaceWalkReflectance(0.0, 1000, 5), 0.0);  // every walk scatters at least once
}

}  // namespace
}  // namespace trazo
