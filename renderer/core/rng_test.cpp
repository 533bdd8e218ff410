// The counter-based sample stream and the per-pass strata.
#include <gtest/gtest.h>

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

TEST(RngStrata, NeighbouringPixelsStartAtDifferentStrata) {
    std::set<uint32_t> firsts;
    for (uint32_t pixel = 0; pixel < 200; ++pixel) firsts.insert(stratumForPass(0, pixel, 1, 0, 100));
    EXPECT_GT(firsts.size(), 70u);  // ~87 distinct values expected for 200 draws from 100
}

}  // namespace
}  // namespace trazo
