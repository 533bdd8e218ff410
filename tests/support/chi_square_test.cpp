// The χ² support: p-values against tables, the Šidák level, pooling, and that it rejects a wrong fit.
#include <gtest/gtest.h>

#include <random>

#include "support/chi_square.h"

namespace trazo {
namespace {

TEST(ChiSquare, PValuesMatchTables) {
    EXPECT_NEAR(chiSquarePValue(3.841459, 1), 0.05, 1e-6);
    EXPECT_NEAR(chiSquarePValue(23.209251, 10), 0.01, 1e-6);
    EXPECT_NEAR(chiSquarePValue(135.806723, 100), 0.01, 1e-6);
    EXPECT_NEAR(chiSquarePValue(67.327563, 100), 0.995, 1e-6);
    for (double x : {0.1, 1.0, 10.0, 50.0}) EXPECT_NEAR(chiSquarePValue(x, 2), std::exp(-0.5 * x), 1e-13);
    // A dof the histograms reach: the upper 1% point of χ²(5000) is 5235.6 (Wilson–Hilferty, good to ~0.1).
    EXPECT_NEAR(chiSquarePValue(5235.6, 5000), 0.01, 1e-4);
    EXPECT_NEAR(chiSquarePValue(5000.0, 5000), 0.4973, 1e-3);
}

TEST(ChiSquare, SidakLevel) {
    EXPECT_NEAR(sidakLevel(0.01, 1), 0.01, 1e-15);
    EXPECT_NEAR(sidakLevel(0.01, 5), 0.0020080, 1e-7);
}

TEST(ChiSquare, AcceptsAFairDieAndRejectsALoadedOne) {
    std::mt19937_64 rng(11);
    std::vector<double> fair(6, 0.0), loaded(6, 0.0), expected(6, 100000.0);
    for (int i = 0; i < 600000; ++i) {
        fair[rng() % 6] += 1.0;
        loaded[rng() % 100 < 17 ? 0 : 1 + rng() % 5] += 1.0;  // face 0 at 17% instead of 16.7%
    }
    const ChiSquareResult f = chiSquareTest(fair, expected), l = chiSquareTest(loaded, expected);
    EXPECT_EQ(f.dof, 5);
    EXPECT_TRUE(f.accepts(0.01)) << f.pValue;
    EXPECT_FALSE(l.accepts(0.01)) << l.pValue;
}

TEST(ChiSquare, PoolsSmallCellsAndRejectsSamplesWhereNoneMayFall) {
    const ChiSquareResult pooled = chiSquareTest({100, 2, 1, 3}, {100, 2, 2, 2});
    EXPECT_EQ(pooled.dof, 1);  // the three small cells pool into one of expected 6
    EXPECT_NEAR(pooled.statistic, 0.0, 1e-12);
    const ChiSquareResult empty = chiSquareTest({99, 1}, {100, 0});
    EXPECT_FALSE(empty.failure.empty());
    EXPECT_FALSE(empty.accepts(0.0));
}

}  // namespace
}  // namespace trazo
