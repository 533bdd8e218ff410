// The path tracer's sample dimensions (path_sampler.h): every power-of-two run of a pixel's passes is a (0,m,2)-net
// in each pair of dimensions, shuffled or not; different pairs do not share their points' leading bits; and each
// half of the accumulation counts its own passes.
#include "integrator/path/path_sampler.h"

#include <gtest/gtest.h>

#include <vector>

namespace trazo {
namespace {

// Whether the points form a (0,m,2)-net: every elementary box 2^-j × 2^-(m−j) holds exactly one of the 2^m.
bool isZeroNet(const std::vector<float>& a, const std::vector<float>& b, int m) {
    const uint32_t n = 1u << m;
    for (int j = 0; j <= m; ++j) {
        std::vector<int> count(n, 0);
        for (uint32_t i = 0; i < n; ++i) {
            const uint32_t x = uint32_t(a[i] * float(1u << j)), y = uint32_t(b[i] * float(1u << (m - j)));
            ++count[(x << (m - j)) | y];
        }
        for (int c : count)
            if (c != 1) return false;
    }
    return true;
}

TEST(PathSampler, EachPairOfDimensionsIsANetOverThePasses) {
    FrameParams frame;
    frame.seed = 7;
    for (uint32_t dimension : {kDimensionPixel, lightPointDimension(0), directionDimension(3)}) {
        for (int m : {4, 8}) {
            std::vector<float> a, b;
            for (uint32_t pass = 0; pass < (1u << m); ++pass) {
                float u, v;
                PathSampler(frame, 1234, pass).get2D(dimension, u, v);
                a.push_back(u);
                b.push_back(v);
            }
            EXPECT_TRUE(isZeroNet(a, b, m)) << "dimension " << dimension << ", 2^" << m << " passes";
        }
    }
}

// With one visiting order for every pair, the pairs' first coordinates would agree in their leading bit (up to a
// fixed flip) in every pass; shuffled, they agree in about half of them.
TEST(PathSampler, PairsAreNotCorrelated) {
    FrameParams frame;
    int agree = 0;
    constexpr int kPasses = 1024;
    for (uint32_t pass = 0; pass < kPasses; ++pass) {
        const PathSampler s(frame, 99, pass);
        agree += (s.get1D(lightChoiceDimension(0)) < 0.5f) == (s.get1D(lobeDimension(0)) < 0.5f);
    }
    EXPECT_NEAR(agree, kPasses / 2, 5 * 16);  // 5σ of a fair coin's count (σ = 16)
}

// Each half of the accumulation is a sequence of its own: the second half's k-th pass is its index k, under a
// different scramble.
TEST(PathSampler, EachHalfCountsItsOwnPasses) {
    FrameParams frame;
    frame.halfBlock = 2;  // passes 0 1 | 2 3 | 4 5 | 6 7: halves 0, 1, 0, 1
    const PathSampler first0(frame, 5, 0), second0(frame, 5, 2), first2(frame, 5, 4), second3(frame, 5, 7);
    EXPECT_EQ(first0.index, 0u);
    EXPECT_EQ(second0.index, 0u);
    EXPECT_EQ(first2.index, 2u);
    EXPECT_EQ(second3.index, 3u);
    EXPECT_NE(first0.key, second0.key);
}

}  // namespace
}  // namespace trazo
