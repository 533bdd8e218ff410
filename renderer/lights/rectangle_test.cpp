// Tests (host) of intersectRectangle against closed forms and its two triangles in double (kind_test_support.h).
#include <gtest/gtest.h>

#include "lights/rectangle.h"
#include "objects/kind_test_support.h"

namespace trazo {
namespace {

using namespace kind_test;

TEST(IntersectRectangle, TwoSidedWithTheShapeNormal) {
    const RectangleShape rect{{0, 2, 0}, {1, 0, 0}, {0, 0, 0.5f}, {0, -1, 0}};
    ShapeHit h;
    h = expectHit(intersectRectangle(rect, {{0.5f, 0, 0.25f}, {0, 1, 0}}, 0, kInf, h), h);  // front
    expectT(h.t, 2, 2);
    expectNormal(h.normal, {0, -1, 0});
    h = expectHit(intersectRectangle(rect, {{0.5f, 5, 0.25f}, {0, -2, 0}}, 0, kInf, h), h);  // back: same normal
    expectT(h.t, 1.5, 5);
    expectNormal(h.normal, {0, -1, 0});
    // Edges and corners belong to it; just outside does not.
    EXPECT_TRUE(intersectRectangle(rect, {{1, 0, 0.5f}, {0, 1, 0}}, 0, kInf, h));
    EXPECT_TRUE(intersectRectangle(rect, {{-1, 0, -0.5f}, {0, 1, 0}}, 0, kInf, h));
    EXPECT_FALSE(intersectRectangle(rect, {{1.0001f, 0, 0}, {0, 1, 0}}, 0, kInf, h));
    EXPECT_FALSE(intersectRectangle(rect, {{0, 0, -0.5001f}, {0, 1, 0}}, 0, kInf, h));
    EXPECT_FALSE(intersectRectangle(rect, {{0, 0, 0}, {1, 0, 0}}, 0, kInf, h));   // parallel
    EXPECT_FALSE(intersectRectangle(rect, {{0, 2, 0}, {1, 0, 0}}, 0, kInf, h));   // in its plane
    EXPECT_FALSE(intersectRectangle(rect, {{0, 0, 0}, {0, -1, 0}}, 0, kInf, h));  // behind
    EXPECT_FALSE(intersectRectangle(rect, {{0, 0, 0}, {0, 1, 0}}, 0, 2.0f, h));   // window
    EXPECT_FALSE(intersectRectangle(rect, {{0, 0, 0}, {0, 1, 0}}, 2.0f, kInf, h));
    EXPECT_TRUE(intersectRectangle(rect, {{0, 0, 0}, {0, 1, 0}}, 1.9f, 2.1f, h));
}

}  // namespace
}  // namespace trazo
