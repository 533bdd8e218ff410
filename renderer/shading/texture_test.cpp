// Texture lookup (bilinear, repeat, bottom-left origin) and tangent-space normal mapping, by hand.
#include "shading/texture.h"

#include <gtest/gtest.h>

#include <vector>

namespace trazo {
namespace {

// 2×2 texture; row 0 is the bottom row: (0,0) red, (1,0) green, (0,1) blue, (1,1) white.
struct TwoByTwo {
    std::vector<Vec3> texels{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1)};
    TextureData tex{0, 2, 2};
    Vec3 at(float u, float v) const { return sampleTexture(tex, texels.data(), u, v); }
};

void expectNear(Vec3 a, Vec3 b, float tolerance = 1e-6f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(TextureLookup, TexelCentresReturnTheTexelAndOriginIsBottomLeft) {
    const TwoByTwo t;
    expectNear(t.at(0.25f, 0.25f), Vec3(1, 0, 0));
    expectNear(t.at(0.75f, 0.25f), Vec3(0, 1, 0));
    expectNear(t.at(0.25f, 0.75f), Vec3(0, 0, 1));
    expectNear(t.at(0.75f, 0.75f), Vec3(1, 1, 1));
}

TEST(TextureLookup, BilinearBetweenCentres) {
    const TwoByTwo t;
    expectNear(t.at(0.5f, 0.25f), Vec3(0.5f, 0.5f, 0));             // halfway red → green
    expectNear(t.at(0.5f, 0.5f), Vec3(0.5f, 0.5f, 0.5f));           // mean of all four
    expectNear(t.at(0.375f, 0.25f), Vec3(0.75f, 0.25f, 0));         // a quarter of the way
}

TEST(TextureLookup, RepeatsOutsideTheUnitSquare) {
    const TwoByTwo t;
    for (float du : {-3.0f, -1.0f, 1.0f, 2.0f})
        for (float dv : {-2.0f, 1.0f}) {
            expectNear(t.at(0.25f + du, 0.75f + dv), t.at(0.25f, 0.75f), 1e-5f);
            expectNear(t.at(0.6f + du, 0.1f + dv), t.at(0.6f, 0.1f), 1e-5f);
        }
    // At u = 0 the left edge blends the first and the last column (wrap), half each.
    expectNear(t.at(0.0f, 0.25f), Vec3(0.5f, 0.5f, 0));
}

TEST(TextureLookup, NanOrHugeCoordinatesStayInside) {
    const TwoByTwo t;
    for (float u : {NAN, INFINITY, -INFINITY, 3e9f}) {
        const Vec3 c = t.at(u, 0.3f);
        EXPECT_TRUE(isFinite(c));
    }
}

TEST(NormalMap, FlatTexelLeavesTheNormal) {
    const Vec3 n = normalize(Vec3(0.2f, 0.9f, -0.3f));
    const Vec3 tangent = normalize(cross(n, Vec3(0, 0, 1)));
    const Vec3 bitangent = cross(n, tangent);
    expectNear(perturbNormal(n, tangent, bitangent, Vec3(0.5f, 0.5f, 1.0f)), n);
}

// m = (0.5, 0, √3/2): the normal turns 30° towards the tangent; m = (0, −0.5, √3/2): 30° away from the
// bitangent (OpenGL convention: green is +bitangent).
TEST(NormalMap, KnownBumpTiltsByHand) {
    const Vec3 n(0, 0, 1), tangent(1, 0, 0), bitangent(0, 1, 0);
    const float c = std::sqrt(3.0f) / 2.0f;
    expectNear(perturbNormal(n, tangent, bitangent, Vec3(0.75f, 0.5f, 0.5f + 0.5f * c)), Vec3(0.5f, 0, c));
    expectNear(perturbNormal(n, tangent, bitangent, Vec3(0.5f, 0.25f, 0.5f + 0.5f * c)), Vec3(0, -0.5f, c));
    // Not unit in the texture: the result is normalised.
    expectNear(perturbNormal(n, tangent, bitangent, Vec3(1.0f, 0.5f, 1.0f)), normalize(Vec3(1, 0, 1)));
}

}  // namespace
}  // namespace trazo
