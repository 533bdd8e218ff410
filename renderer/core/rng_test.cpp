// The counter-based sample stream and the per-pass strata.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "core/rng.h"

namespace trazo {
namespace {

TEST(RngStream, IsAPureFunctionOfSeedPixelPassAndDimension) {
    SampleStream a(7, 1234, 5), b(7, 1234, 5);
    for (int i = 0; i < 100; ++i) ASSERT_EQ(a.nextBits(), b.nextBits());
    SampleStream c(8, 1234, 5), d(7, 1235, 5), e(7, 1234, 6);
    const uint32_t first = SampleStream(7, 1234, 5).nextBits();
    EXPECT_NE(first, c.nextBits());
    EXPECT_NE(first, d.nextBits());
    EXPECT_NE(first, e.nextBits());
}

TEST(RngStream, UniformInUnitInterval) {
    // Chi-square over 64 bins with 640k draws from many pixels: far below the 0.1% tail (about 105 for 63 dof).
    std::vector<int> bins(64, 0);
    const int pixels = 10000, perPixel = 64;
    for (int p = 0; p < pixels; ++p) {
        SampleStream s(1, p, 0);
        for (int i = 0; i < perPixel; ++i) {
            const float x = s.next();
            ASSERT_GE(x, 0.0f);
            ASSERT_LT(x, 1.0f);
            bins[int(x * 64)]++;
        }
    }
    const double expected = double(pixels) * perPixel / 64;
    double chi2 = 0;
    for (int b : bins) chi2 += (b - expected) * (b - expected) / expected;
    EXPECT_LT(chi2, 105.0);
}

TEST(RngStrata, EveryCycleVisitsEveryStratumOnce) {
    for (uint32_t count : {1u, 4u, 16u, 18u, 100u}) {
        for (uint32_t pixel = 0; pixel < 50; ++pixel) {
            std::set<uint32_t> seen;
            for (uint32_t pass = 0; pass < count; ++pass) seen.insert(stratumForPass(3, pixel, 9, pass, count));
            ASSERT_EQ(seen.size(), count);
            ASSERT_LT(*seen.rbegin(), count);
        }
    }
}

// Passes p and p + count take the same stratum (the next cycle repeats the order), for any cycle.
TEST(RngStrata, CyclesRepeatTheSameOrder) {
    for (uint32_t count : {3u, 25u, 64u, 1000u})
        for (uint32_t pass = 0; pass < 2 * count; ++pass)
            ASSERT_EQ(stratumForPass(5, 77, 2, pass, count), stratumForPass(5, 77, 2, pass + 3 * count, count));
}

// The first quarter of a 10×10 cycle is spread over the grid, not swept along a few rows: a sweep puts all
// 25 in 3 rows (10 in the fullest); a random order without replacement puts about 5 in the fullest row.
TEST(RngStrata, FirstPassesOfACycleSpreadOverTheGrid) {
    double fullestRow = 0;
    for (uint32_t pixel = 0; pixel < 1000; ++pixel) {
        int rows[10] = {};
        for (uint32_t pass = 0; pass < 25; ++pass) ++rows[stratumForPass(1, pixel, 16, pass, 100) / 10];
        fullestRow += *std::max_element(rows, rows + 10);
    }
    EXPECT_LT(fullestRow / 1000, 6.0);
}

TEST(RngStrata, NeighbouringPixelsStartAtDifferentStrata) {
    std::set<uint32_t> firsts;
    for (uint32_t pixel = 0; pixel < 200; ++pixel) firsts.insert(stratumForPass(0, pixel, 1, 0, 100));
    EXPECT_GT(firsts.size(), 70u);  // ~87 distinct values expected for 200 draws from 100
}

}  // namespace
}  // namespace trazo
