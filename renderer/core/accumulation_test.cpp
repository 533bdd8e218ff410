// Tests of AccumPixel: weighted sums into both halves, and the estimate every image is made of.
#include "core/accumulation.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "render/resolve.h"

namespace trazo {
namespace {

void expectVec3(Vec3 got, Vec3 want) {
    EXPECT_EQ(got.x, want.x);
    EXPECT_EQ(got.y, want.y);
    EXPECT_EQ(got.z, want.z);
}

TEST(Accumulation, AnEmptyPixelIsBlack) {
    const AccumPixel empty{};
    expectVec3(empty.estimate(), Vec3(0.0f));
    AccumPixel negative{{1, 1, 1}, -1.0, {0, 0, 0}, 0.0};  // never made by add(); still no division by it
    expectVec3(negative.estimate(), Vec3(0.0f));
}

TEST(Accumulation, AddWeighsAndSplitsTheHalves) {
    AccumPixel p{};
    p.add(Vec3(1.0f, 2.0f, 3.0f), false, 1.0f);
    p.add(Vec3(3.0f, 2.0f, 1.0f), true, 3.0f);
    EXPECT_EQ(p.count, 4.0);
    EXPECT_EQ(p.countB, 3.0);
    EXPECT_EQ(p.sum[0], 10.0);
    EXPECT_EQ(p.sumB[2], 3.0);
    expectVec3(p.estimate(), Vec3(2.5f, 2.0f, 1.5f));
}

// The estimate is the double quotient rounded once to float; resolveImage returns exactly that per pixel.
TEST(Accumulation, EstimateIsTheDoubleQuotientRoundedOnce) {
    const AccumPixel p{{1.0, 2.0, 1e-3}, 3.0, {0, 0, 0}, 0.0};
    const Vec3 e = p.estimate();
    EXPECT_EQ(e.x, float(1.0 / 3.0));
    EXPECT_EQ(e.y, float(2.0 / 3.0));
    EXPECT_EQ(e.z, float(1e-3 / 3.0));
    const std::vector<Vec3> image = resolveImage({p, AccumPixel{}});
    ASSERT_EQ(image.size(), 2u);
    EXPECT_EQ(std::memcmp(&image[0], &e, sizeof e), 0);
    expectVec3(image[1], Vec3(0.0f));
}

}  // namespace
}  // namespace trazo
