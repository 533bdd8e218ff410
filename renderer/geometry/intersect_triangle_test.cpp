// Tests of the watertight ray–triangle intersection: analytic hits, both sides, ranges, shared edges and vertices.
#include "geometry/intersect_triangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/counter_uniform.h"

namespace trazo {
namespace {

bool hitTriangle(const Ray& ray, Vec3 p0, Vec3 p1, Vec3 p2, TriangleHit& hit, float tMin = 0.0f,
                 float tMax = INFINITY) {
    return intersectTriangle(makeTriangleRay(ray), p0, p1, p2, tMin, tMax, hit);
}

TEST(TriangleIntersect, AxisAlignedHitGivesExactDistanceAndBarycentrics) {
    TriangleHit hit;
    ASSERT_TRUE(hitTriangle({{0.25f, 0.5f, 2.0f}, {0, 0, -1}}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, hit));
    EXPECT_EQ(hit.t, 2.0f);
    EXPECT_EQ(hit.b1, 0.25f);
    EXPECT_EQ(hit.b2, 0.5f);
}

TEST(TriangleIntersect, ObliqueHitMatchesConstructedPoint) {
    const Vec3 p0(1, 2, 3), p1(4, 2.5f, 3.5f), p2(1.5f, 5, 2);
    const Vec3 target = p0 + (p1 - p0) * 0.2f + (p2 - p0) * 0.3f;
    const Vec3 d = normalize(Vec3(0.3f, -0.5f, 0.8f));
    const Ray ray{target - d * 1.5f, d};
    TriangleHit hit;
    ASSERT_TRUE(hitTriangle(ray, p0, p1, p2, hit));
    EXPECT_NEAR(hit.t, 1.5f, 1e-5f);
    EXPECT_NEAR(hit.b1, 0.2f, 1e-5f);
    EXPECT_NEAR(hit.b2, 0.3f, 1e-5f);
    // The same point reached from the other side (two-sided).
    ASSERT_TRUE(hitTriangle({target + d * 2.5f, -d}, p0, p1, p2, hit));
    EXPECT_NEAR(hit.t, 2.5f, 1e-5f);
    EXPECT_NEAR(hit.b1, 0.2f, 1e-5f);
    EXPECT_NEAR(hit.b2, 0.3f, 1e-5f);
}

TEST(TriangleIntersect, BothSidesHit) {
    TriangleHit hit;
    ASSERT_TRUE(hitTriangle({{0.25f, 0.25f, -3.0f}, {0, 0, 1}}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, hit));
    EXPECT_EQ(hit.t, 3.0f);
    ASSERT_TRUE(hitTriangle({{0.25f, 0.25f, 3.0f}, {0, 0, -1}}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, hit));
    EXPECT_EQ(hit.t, 3.0f);
}

TEST(TriangleIntersect, MissesOutsideAndParallel) {
    TriangleHit hit;
    EXPECT_FALSE(hitTriangle({{0.75f, 0.75f, 2.0f}, {0, 0, -1}}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, hit));
    // Parallel above the plane, and inside the plane through the triangle.
    EXPECT_FALSE(hitTriangle({{-1.0f, 0.25f, 1.0f}, {1, 0, 0}}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, hit));
    EXPECT_FALSE(hitTriangle({{-1.0f, 0.25f, 0.0f}, {1, 0, 0}}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, hit));
    // Pointing away.
    EXPECT_FALSE(hitTriangle({{0.25f, 0.25f, 2.0f}, {0, 0, 1}}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, hit));
}

TEST(TriangleIntersect, RespectsOpenDistanceRange) {
    const Ray ray{{0.25f, 0.25f, 2.0f}, {0, 0, -1}};
    TriangleHit hit;
    EXPECT_FALSE(hitTriangle(ray, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, hit, 0.0f, 2.0f));
    EXPECT_TRUE(hitTriangle(ray, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, hit, 0.0f, std::nextafter(2.0f, 3.0f)));
    EXPECT_FALSE(hitTriangle(ray, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, hit, 2.0f, 10.0f));
    EXPECT_TRUE(hitTriangle(ray, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, hit, std::nextafter(2.0f, 0.0f), 10.0f));
}

TEST(TriangleIntersect, DegenerateTrianglesMiss) {
    TriangleHit hit;
    const Ray ray{{0.5f, 0.0f, 2.0f}, {0, 0, -1}};
    EXPECT_FALSE(hitTriangle(ray, {0.5f, 0, 0}, {0.5f, 0, 0}, {0.5f, 0, 0}, hit));
    EXPECT_FALSE(hitTriangle(ray, {0, 0, 0}, {0.5f, 0, 0}, {1, 0, 0}, hit));
}

// Rays aimed at random points of an edge shared by two triangles (on either side of it) hit at least one.
TEST(TriangleIntersect, SharedEdgeNeverLetsARayThrough) {
    CounterUniform u(7);
    int leaks = 0;
    for (int k = 0; k < 200; ++k) {
        const Vec3 a = u.point(1.0f), b = u.point(1.0f);
        const Vec3 side = cross(b - a, u.point(1.0f));
        const Vec3 mid = lerp(a, b, 0.5f);
        // Coplanar wings on opposite sides, so no view direction folds one over the other.
        const Vec3 c = mid + side + (b - a) * u(-0.5f, 0.5f);
        const Vec3 d = mid - side * u(0.5f, 2.0f) + (b - a) * u(-0.5f, 0.5f);
        for (int i = 0; i < 500; ++i) {
            const Vec3 origin = u.point(4.0f);
            const Vec3 target = lerp(a, b, u(0.0f, 1.0f));
            const Ray ray{origin, target - origin};
            const TriangleRay tr = makeTriangleRay(ray);
            TriangleHit h;
            const bool hitAbc = intersectTriangle(tr, a, b, c, 0.0f, INFINITY, h);
            const bool hitBad = intersectTriangle(tr, b, a, d, 0.0f, INFINITY, h);
            leaks += !hitAbc && !hitBad;
        }
    }
    EXPECT_EQ(leaks, 0);
    // Exactly-on-edge rays are rare with random targets; the axis-aligned case below forces them.
    TriangleHit h;
    const Ray diagonal{{0.5f, 0.5f, 1.0f}, {0, 0, -1}};
    EXPECT_TRUE(hitTriangle(diagonal, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, h));
    EXPECT_TRUE(hitTriangle(diagonal, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}, h));
}

// A fan of triangles around one vertex: rays aimed at that vertex hit at least one of them.
TEST(TriangleIntersect, SharedVertexNeverLetsARayThrough) {
    CounterUniform u(11);
    int leaks = 0;
    for (int k = 0; k < 100; ++k) {
        const Vec3 center = u.point(1.0f);
        const Vec3 n = normalize(u.point(1.0f)), e1 = anyOrthonormal(n), e2 = cross(n, e1);
        constexpr int kFan = 7;
        Vec3 rim[kFan];
        for (int j = 0; j < kFan; ++j) {
            const float phi = 6.2831853f * (float)j / kFan;
            rim[j] = center + (e1 * std::cos(phi) + e2 * std::sin(phi)) * u(0.5f, 1.5f) + n * u(-0.2f, 0.2f);
        }
        for (int i = 0; i < 1000; ++i) {
            // Within ~25° of the normal and the rim tilts ≤ ~22°: seen from there the fan never folds over.
            Vec3 origin = center + n * u(2.0f, 4.0f) + u.point(0.5f);
            if (i % 2) origin = center - (origin - center);  // from below too
            const TriangleRay tr = makeTriangleRay({origin, center - origin});
            bool any = false;
            for (int j = 0; j < kFan; ++j) {
                TriangleHit h;
                any |= intersectTriangle(tr, center, rim[j], rim[(j + 1) % kFan], 0.0f, INFINITY, h);
            }
            leaks += !any;
        }
    }
    EXPECT_EQ(leaks, 0);
}

}  // namespace
}  // namespace trazo
