// Unit tests of the error estimate and the half split, on synthetic samples (a backend whose "render" draws
// known random values: fake_backend.h), so the statistics are exact and quick.
#include "render/error_estimate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "core/rng.h"
#include "render/fake_backend.h"
#include "render/progressive_render.h"

namespace trazo {
namespace {

using test::FakeBackend;

TEST(ErrorEstimate, FormulaOnTwoPixels) {
    // Pixel 0: first half 2 samples summing to (2,4,6), second half 2 samples summing to (4,4,4).
    std::vector<AccumPixel> accum(2);
    accum[0] = AccumPixel{{6, 8, 10}, 4.0, {4, 4, 4}, 2.0};
    accum[1] = AccumPixel{{4, 4, 4}, 4.0, {2, 2, 2}, 2.0};  // halves agree: no error
    const ErrorEstimate e = estimateError(accum);
    ASSERT_TRUE(e.available);
    // Pixel 0: A = (1,2,3), B = (2,2,2), d = (-1,0,1); w = 2·2/16 = 1/4; variance sum = 0.25·2 = 0.5.
    EXPECT_NEAR(e.rmse, std::sqrt(0.5 / 6.0), 1e-9);
    EXPECT_NEAR(e.meanValue, (1.5 + 2 + 2.5 + 1 + 1 + 1) / 6.0, 1e-9);
    EXPECT_NEAR(e.relError, e.rmse / e.meanValue, 1e-12);
    EXPECT_EQ(e.passes, 4u);
    EXPECT_EQ(e.secondHalfPasses, 2u);
}

TEST(ErrorEstimate, UnavailableWithOneHalfEmpty) {
    std::vector<AccumPixel> accum(3, AccumPixel{{1, 1, 1}, 1.0, {0, 0, 0}, 0.0});
    const ErrorEstimate e = estimateError(accum);
    EXPECT_FALSE(e.available);
    EXPECT_TRUE(std::isnan(e.relError));
    EXPECT_NEAR(e.meanValue, 1.0, 1e-12);
}

TEST(ErrorEstimate, AddSplitsIntoTheSecondHalf) {
    AccumPixel p{};
    p.add(Vec3(1.0f), false, 1.0f);
    p.add(Vec3(2.0f), true, 1.0f);
    EXPECT_EQ(p.count, 2.0);
    EXPECT_EQ(p.sum[0], 3.0);
    EXPECT_EQ(p.countB, 1.0);
    EXPECT_EQ(p.sumB[0], 2.0);
    EXPECT_EQ(p.estimate().x, 1.5f);
}

// Past 2^24 samples a float count stops counting and a float sum stops growing; the accumulation's doubles
// keep both exact, at the viewer's weights too.
TEST(ErrorEstimate, AccumulationCountsPast2To24) {
    for (float weight : {1.0f, 100.0f}) {
        AccumPixel p{};
        const uint32_t samples = (1u << 24) + 1000u;
        for (uint32_t i = 0; i < samples; ++i) p.add(Vec3(0.25f, 1.0f, 3.0f), (i & 1u) != 0, weight);
        EXPECT_EQ(p.count, double(samples) * weight);
        EXPECT_EQ(p.countB, double(samples / 2) * weight);
        EXPECT_EQ(p.estimate().x, 0.25f);
        EXPECT_EQ(p.estimate().z, 3.0f);
    }
}

TEST(ErrorEstimate, CompareToReference) {
    const std::vector<Vec3> ref{Vec3(1, 1, 1), Vec3(3, 3, 3)};
    const std::vector<Vec3> img{Vec3(1, 1, 1), Vec3(3, 3, 3.6f)};
    const ReferenceError r = compareToReference(img, ref);
    EXPECT_NEAR(r.rmse, std::sqrt(0.36 / 6), 1e-6);
    EXPECT_NEAR(r.relError, std::sqrt(0.36 / 6) / 2.0, 1e-6);
    EXPECT_NEAR(r.relMse, 0.36 / 9.01 / 6, 1e-6);
}

// Over every 2·cycle passes each half takes every stratum of every grid (N | cycle) equally often.
TEST(HalfSplit, BalancedOverTwoCyclesForEveryGrid) {
    for (uint32_t cycle : {1u, 2u, 12u, 16u, 18u, 100u, 200u, 800u, 1536u}) {
        EXPECT_EQ(cycle % halfBlockPasses(cycle), 0u);
        EXPECT_EQ((cycle / halfBlockPasses(cycle)) % 2, 1u) << "block is the largest power of 2 in " << cycle;
        for (uint32_t n = 1; n <= cycle; ++n) {
            if (cycle % n) continue;
            std::vector<int> balance(n, 0);
            for (uint32_t offset : {0u, 7u}) {
                std::fill(balance.begin(), balance.end(), 0);
                FrameParams frame{};
                frame.halfBlock = halfBlockPasses(cycle);
                for (uint32_t v = 0; v < 2 * cycle; ++v) balance[(offset + v) % n] += frame.inSecondHalf(v) ? 1 : -1;
                for (uint32_t s = 0; s < n; ++s) ASSERT_EQ(balance[s], 0) << "cycle " << cycle << " grid " << n;
            }
        }
    }
}

// With the split following the cycle the estimate matches the true error at multiples of 2·cycle; split by
// plain parity instead, the halves see different strata and it reads too high, more so with more passes.
TEST(ErrorEstimate, StratifiedHalvesBracketTheTruth) {
    constexpr uint32_t kStrata = 12;
    FakeBackend backend(20000, kStrata, 0.02f);
    const FrameParams frame{};
    for (uint32_t passes : {24u, 48u, 96u}) {
        backend.reset();
        renderPassRange(backend, frame, 0, passes, kStrata);
        std::vector<AccumPixel> accum;
        backend.readAccumulation(accum);
        const double estimate = estimateError(accum).relError, truth = backend.trueRelError();
        EXPECT_GT(estimate, truth / 1.25) << passes << " passes";
        EXPECT_LT(estimate, truth * 1.25) << passes << " passes";

        backend.reset();
        renderPassRange(backend, frame, 0, passes, 1);  // parity split: wrong for 12 strata
        backend.readAccumulation(accum);
        // The parity halves differ by a fixed amount (odd against even strata): the bias does not shrink.
        if (passes >= 48) {
            EXPECT_GT(estimateError(accum).relError, 2.0 * backend.trueRelError()) << passes;
        }
    }
}

}  // namespace
}  // namespace trazo
