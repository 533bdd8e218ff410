// Tests (host) of intersectBox against closed forms and its double-precision oracle (kind_test_support.h).
#include <gtest/gtest.h>

#include "core/affine.h"
#include "objects/box.h"
#include "objects/kind_test_support.h"

namespace trazo {
namespace {

using namespace kind_test;

BoxShape axisAlignedBox(Vec3 size, Vec3 centre) {
    const Affine3 w = then(makeScale(size), makeTranslation(centre));
    return {inverse(w), w};
}

TEST(IntersectBox, AxisAlignedHitsFromOutside) {
    const BoxShape box = axisAlignedBox({2, 4, 6}, {1, 2, 3});  // [0,2]×[0,4]×[0,6]
    ShapeHit h;
    h = expectHit(intersectBox(box, {{1, 2, 20}, {0, 0, -1}}, 0, kInf, h), h);
    expectT(h.t, 14, 20);
    expectNormal(h.normal, {0, 0, 1});
    h = expectHit(intersectBox(box, {{-3, 1, 1}, {2, 0, 0}}, 0, kInf, h), h);
    expectT(h.t, 1.5, 4);
    expectNormal(h.normal, {-1, 0, 0});
    h = expectHit(intersectBox(box, {{1, 10, 5}, {0, -1, 0}}, 0, kInf, h), h);
    expectT(h.t, 6, 10);
    expectNormal(h.normal, {0, 1, 0});
}

TEST(IntersectBox, Misses) {
    const BoxShape box = axisAlignedBox({2, 4, 6}, {1, 2, 3});
    ShapeHit h;
    EXPECT_FALSE(intersectBox(box, {{3, 2, 20}, {0, 0, -1}}, 0, kInf, h));        // beside
    EXPECT_FALSE(intersectBox(box, {{1, 2, 20}, {0, 0, 1}}, 0, kInf, h));         // behind
    EXPECT_FALSE(intersectBox(box, {{-1, -1, 3}, {1, 1.2f, 10}}, 0, kInf, h));    // slabs don't overlap
    EXPECT_FALSE(intersectBox(box, {{-2, 5, 3}, {1, 0.4f, 0}}, 0, kInf, h));      // past a corner
}

TEST(IntersectBox, ZeroAndNegativeZeroDirectionComponents) {
    const BoxShape box = axisAlignedBox({1, 1, 1}, {0, 0, 0});
    ShapeHit h;
    for (float zero : {0.0f, -0.0f}) {
        h = expectHit(intersectBox(box, {{0.25f, -0.25f, 3}, {zero, zero, -1}}, 0, kInf, h), h);
        expectT(h.t, 2.5, 3);
        expectNormal(h.normal, {0, 0, 1});
        h = expectHit(intersectBox(box, {{zero, zero, 3}, {zero, zero, -2}}, 0, kInf, h), h);
        expectT(h.t, 1.25, 3);
        EXPECT_FALSE(intersectBox(box, {{0.75f, 0, 3}, {zero, 0, -1}}, 0, kInf, h));
        EXPECT_FALSE(intersectBox(box, {{-0.75f, 0, 3}, {zero, 0, -1}}, 0, kInf, h));
        h = expectHit(intersectBox(box, {{-3, 0.1f, 0.2f}, {1, zero, zero}}, 0, kInf, h), h);
        expectT(h.t, 2.5, 3);
        expectNormal(h.normal, {-1, 0, 0});
        // From inside, parallel to two slabs.
        h = expectHit(intersectBox(box, {{0.1f, 0.2f, 0.3f}, {zero, -1, zero}}, 0, kInf, h), h);
        expectT(h.t, 0.7, 1);
        expectNormal(h.normal, {0, -1, 0});
    }
}

TEST(IntersectBox, RayInAFacePlaneTouchesTheClosedBox) {
    // Along the top face y = 0.5: inside that slab (closed), so it meets the −x face at t = 4.5.
    const BoxShape box = axisAlignedBox({1, 1, 1}, {0, 0, 0});
    ShapeHit h;
    h = expectHit(intersectBox(box, {{-5, 0.5f, 0}, {1, 0, 0}}, 0, kInf, h), h);
    expectT(h.t, 4.5, 5);
    expectNormal(h.normal, {-1, 0, 0});
    EXPECT_FALSE(intersectBox(box, {{-5, 0.5000001f, 0}, {1, 0, 0}}, 0, kInf, h));
    // Along an edge, and grazing a face at a tiny angle (enters through the top at x = 0.5 − 1e-6·…).
    h = expectHit(intersectBox(box, {{-5, 0.5f, 0.5f}, {1, 0, 0}}, 0, kInf, h), h);
    expectT(h.t, 4.5, 5);
    const float height = 0.5f + 5e-6f, slope = -1e-6f;
    h = expectHit(intersectBox(box, {{-5, height, 0}, {1, slope, 0}}, 0, kInf, h), h);
    EXPECT_NEAR(h.t, (0.5 - double(height)) / slope, 1e-5);
    expectNormal(h.normal, {0, 1, 0});
}

TEST(IntersectBox, OriginInsideHitsExitWithOutwardNormal) {
    const BoxShape box = axisAlignedBox({2, 4, 6}, {1, 2, 3});
    ShapeHit h;
    h = expectHit(intersectBox(box, {{1, 2, 3}, {0, 0, -1}}, 0, kInf, h), h);
    expectT(h.t, 3, 6);
    expectNormal(h.normal, {0, 0, -1});
    h = expectHit(intersectBox(box, {{1.5f, 2, 3}, {0.5f, 0, 0}}, 0, kInf, h), h);
    expectT(h.t, 1, 4);
    expectNormal(h.normal, {1, 0, 0});
}

TEST(IntersectBox, Window) {
    const BoxShape box = axisAlignedBox({1, 1, 1}, {0, 0, 0});
    const Ray ray{{0, 0, 5}, {0, 0, -1}};  // enters at 4.5, leaves at 5.5
    ShapeHit h;
    h = expectHit(intersectBox(box, ray, 4.6f, kInf, h), h);
    expectT(h.t, 5.5, 6);
    expectNormal(h.normal, {0, 0, -1});
    EXPECT_FALSE(intersectBox(box, ray, 0, 4.5f, h));
    EXPECT_FALSE(intersectBox(box, ray, 5.5f, kInf, h));
}

TEST(IntersectBox, RotatedAndScaledBoxMatchesTriangles) {
    // Exact cases on a sheared, non-uniformly scaled box: straight down a face normal onto the face's
    // centre, the hit is at the distance the ray started from; its normal is that face's.
    const BoxShape box = makeBox(1.0f, {0, 0, 0});
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {-1.0f, 1.0f}) {
            const Vec3 n = normalize(box.objectFromWorld.row[axis] * sign);
            Vec3 faceCentreObject(0.0f);
            faceCentreObject[axis] = 0.5f * sign;
            const Vec3 faceCentre = box.worldFromObject.applyToPoint(faceCentreObject);
            const Ray ray{faceCentre + n * 10.0f, -n};
            const Reference ref = boxOracle(box, toD(ray), 0, kInf, 0);
            ShapeHit h;
            h = expectHit(intersectBox(box, ray, 0, kInf, h), h);
            ASSERT_TRUE(ref.hit);
            EXPECT_NEAR(h.t, 10, 16 * kEps * 10);
            EXPECT_NEAR(ref.t, 10, 16 * kEps * 10);
            expectNormal(h.normal, n, 8 * kEps);
            expectNormal(toF(ref.normal), n, 8 * kEps);
        }
    }
}

}  // namespace
}  // namespace trazo
