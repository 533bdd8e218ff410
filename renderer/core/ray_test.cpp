// nextFloatUp/Down against libm's nextafterf, bit for bit, over every exponent, both signs, zeros,
// subnormals, the largest finite values, infinities and NaN.
#include "core/ray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace trazo {
namespace {

uint32_t bitsOf(float v) {
    uint32_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
}

TEST(NextFloat, MatchesNextafterBitForBit) {
    std::vector<float> values{0.0f, -0.0f, 1.4e-45f, -1.4e-45f, 1.17549435e-38f, -1.17549435e-38f,
                              std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(),
                              INFINITY, -INFINITY};
    for (uint32_t bits = 0; bits < 0x7f800000u; bits += 0x00012345u) {  // every exponent, many mantissas
        float v;
        std::memcpy(&v, &bits, sizeof v);
        values.push_back(v);
        values.push_back(-v);
    }
    for (float v : values) {
        ASSERT_EQ(bitsOf(nextFloatUp(v)), bitsOf(std::nextafterf(v, INFINITY))) << v;
        ASSERT_EQ(bitsOf(nextFloatDown(v)), bitsOf(std::nextafterf(v, -INFINITY))) << v;
    }
    EXPECT_TRUE(std::isnan(nextFloatUp(NAN)));
    EXPECT_TRUE(std::isnan(nextFloatDown(NAN)));
}

// offsetRayOrigin moves the point off the surface, by its error bound and one ulp more, to the side `towards`
// points at.
TEST(OffsetRayOrigin, LeavesTheSurfaceOnTheRequestedSide) {
    const Vec3 p(1.0f, 2.0f, 0.0f), error(1e-6f, 1e-6f, 1e-6f), n(0.0f, 0.0f, 1.0f);
    EXPECT_GT(offsetRayOrigin(p, error, n, Vec3(0.3f, 0.0f, 1.0f)).z, 0.0f);
    EXPECT_LT(offsetRayOrigin(p, error, n, Vec3(0.3f, 0.0f, -1.0f)).z, 0.0f);
    const float bound = 1e-6f;  // |ng|·pError along z
    EXPECT_GT(offsetRayOrigin(p, error, n, n).z, bound);
}

}  // namespace
}  // namespace trazo
