// Tests (host) of intersectCylinder against closed forms and its double-precision oracle (kind_test_support.h).
#include <gtest/gtest.h>

#include <cmath>

#include "objects/cylinder.h"
#include "objects/kind_test_support.h"

namespace trazo {
namespace {

using namespace kind_test;

TEST(IntersectCylinder, SideHitFromOutside) {
    const CylinderShape c{{1, 0, 2}, {0, 1, 0}, 3, 0.5f};
    ShapeHit h;
    h = expectHit(intersectCylinder(c, {{1, 1, 10}, {0, 0, -1}}, 0, kInf, h), h);
    expectT(h.t, 7.5, 10);
    expectNormal(h.normal, {0, 0, 1});
    // Off-centre: x offset 0.3 → enters at z = 2 + 0.4.
    h = expectHit(intersectCylinder(c, {{1.3f, 1, 10}, {0, 0, -2}}, 0, kInf, h), h);
    expectT(h.t, 3.8, 10);
    expectNormal(h.normal, {0.6f, 0, 0.8f});
    EXPECT_FALSE(intersectCylinder(c, {{1, 3.1f, 10}, {0, 0, -1}}, 0, kInf, h));  // above the top
    EXPECT_FALSE(intersectCylinder(c, {{1.6f, 1, 10}, {0, 0, -1}}, 0, kInf, h));  // beside
}

TEST(IntersectCylinder, ParallelToTheAxisThroughTheCaps) {
    for (const Vec3 axisIn : {Vec3(0, 1, 0), Vec3(0, 0, -1), Vec3(1, 2, 3)}) {
        const Vec3 axis = normalize(axisIn);
        const CylinderShape c{{1, -2, 0.5f}, axis, 3, 0.5f};
        const Vec3 side = anyOrthonormal(axis);
        ShapeHit h;
        // From below along the axis (the side quadratic is degenerate): bottom cap, normal −axis.
        for (const Vec3 radial : {Vec3(0, 0, 0), side * 0.3f, side * 0.49f}) {
            h = expectHit(intersectCylinder(c, {c.base + radial - axis * 2.0f, axis}, 0, kInf, h), h);
            expectT(h.t, 2, 8, 8);
            expectNormal(h.normal, -axis, 4 * kEps);
            // From above, direction −2·axis: top cap at t = (5 − 3)/2.
            h = expectHit(intersectCylinder(c, {c.base + radial + axis * 5.0f, axis * -2.0f}, 0, kInf, h), h);
            expectT(h.t, 1, 8, 8);
            expectNormal(h.normal, axis, 4 * kEps);
            // From inside: exit through the top cap.
            h = expectHit(intersectCylinder(c, {c.base + radial + axis * 1.0f, axis}, 0, kInf, h), h);
            expectT(h.t, 2, 8, 8);
            expectNormal(h.normal, axis, 4 * kEps);
        }
        EXPECT_FALSE(intersectCylinder(c, {c.base + side * 0.51f - axis * 2.0f, axis}, 0, kInf, h));
    }
}

TEST(IntersectCylinder, RayAlongTheSideLineTouchesTheRim) {
    const CylinderShape c{{0, 0, 0}, {0, 1, 0}, 1, 0.5f};
    ShapeHit h;
    h = expectHit(intersectCylinder(c, {{0.5f, -5, 0}, {0, 1, 0}}, 0, kInf, h), h);
    expectT(h.t, 5, 5);
    expectNormal(h.normal, {0, -1, 0});
    EXPECT_FALSE(intersectCylinder(c, {{0.5000001f, -5, 0}, {0, 1, 0}}, 0, kInf, h));
}

TEST(IntersectCylinder, ParallelToTheCaps) {
    const CylinderShape c{{0, 0, 0}, {0, 1, 0}, 1, 0.5f};
    ShapeHit h;
    h = expectHit(intersectCylinder(c, {{-3, 0.5f, 0}, {1, 0, 0}}, 0, kInf, h), h);
    expectT(h.t, 2.5, 3);
    expectNormal(h.normal, {-1, 0, 0});
    // In a cap's plane (closed cylinder): the side still counts at height 0 and 1.
    h = expectHit(intersectCylinder(c, {{-3, 0, 0}, {1, 0, 0}}, 0, kInf, h), h);
    expectT(h.t, 2.5, 3);
    h = expectHit(intersectCylinder(c, {{-3, 1, 0}, {1, 0, 0}}, 0, kInf, h), h);
    expectT(h.t, 2.5, 3);
    EXPECT_FALSE(intersectCylinder(c, {{-3, 1.001f, 0}, {1, 0, 0}}, 0, kInf, h));
    EXPECT_FALSE(intersectCylinder(c, {{-3, -0.001f, 0}, {1, 0, 0}}, 0, kInf, h));
}

TEST(IntersectCylinder, TangentToTheSide) {
    const CylinderShape c{{0, 0, 0}, {0, 1, 0}, 1, 0.5f};
    ShapeHit h;
    h = expectHit(intersectCylinder(c, {{-3, 0.5f, 0.5f}, {1, 0, 0}}, 0, kInf, h), h);
    expectT(h.t, 3, 3);
    expectNormal(h.normal, {0, 0, 1});
    EXPECT_FALSE(intersectCylinder(c, {{-3, 0.5f, 0.5000001f}, {1, 0, 0}}, 0, kInf, h));
}

TEST(IntersectCylinder, OriginInsideAndWindow) {
    const CylinderShape c{{0, 0, 0}, {0, 1, 0}, 2, 1};
    ShapeHit h;
    h = expectHit(intersectCylinder(c, {{0, 1, 0}, {0, 0, 1}}, 0, kInf, h), h);
    expectT(h.t, 1, 2);
    expectNormal(h.normal, {0, 0, 1});
    h = expectHit(intersectCylinder(c, {{0, 1, 0}, {0, -0.5f, 0}}, 0, kInf, h), h);
    expectT(h.t, 2, 2);
    expectNormal(h.normal, {0, -1, 0});
    const Ray ray{{-5, 1, 0}, {1, 0, 0}};  // side at 4 and 6
    h = expectHit(intersectCylinder(c, ray, 4.5f, kInf, h), h);
    expectT(h.t, 6, 6);
    expectNormal(h.normal, {1, 0, 0});
    EXPECT_FALSE(intersectCylinder(c, ray, 0, 4.0f, h));
    EXPECT_FALSE(intersectCylinder(c, ray, 6.0f, kInf, h));
    // Through a cap and then the side: the cap is nearer.
    h = expectHit(intersectCylinder(c, {{0, 2.5f, 0}, toF(normalize(DVec{1, -1, 0}))}, 0, kInf, h), h);
    expectT(h.t, std::sqrt(0.5), 3);
    expectNormal(h.normal, {0, 1, 0});
}

TEST(IntersectCylinder, NearlyParallelToTheAxisMatchesTheOracle) {
    const CylinderShape c = makeCylinder(1.0f, {0, 0, 0});
    const ShapeCase sc = cylinderCase(1.0f, {0, 0, 0});
    const Vec3 side = anyOrthonormal(c.axis);
    Tally tally;
    for (double angle : {1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2}) {
        for (double along : {-1.0, 0.5, 3.0}) {
            for (double radial : {0.0, 0.3, 0.59}) {
                const DVec dir = normalize(toD(c.axis) * std::cos(angle) + toD(side) * std::sin(angle));
                const Vec3 o = toF(toD(c.base) + toD(c.axis) * along + toD(cross(c.axis, side)) * radial);
                compareOne(sc, {o, toF(dir)}, 0, kInf, tally);
                compareOne(sc, {o, toF(dir * -1.0)}, 0, kInf, tally);
            }
        }
    }
    expectClean(tally, "nearly parallel to the axis");
}

TEST(IntersectCylinder, LongPoleSeenNearlyAlongItsAxis) {
    // Side hits at t ≈ r/sin θ: |axis × d| = sin θ must be right to ε relative, not to ε/θ (a plain
    // cross product of nearly parallel vectors), or t is off by 1e-4 already at θ = 1e-3.
    const CylinderShape c{{0.3f, -0.2f, 0.1f}, normalize(Vec3(1.0f, 2.0f, -0.5f)), 1000.0f, 0.1f};
    const ShapeCase sc{[c](const Ray& r, float a, float b, ShapeHit& h) { return intersectCylinder(c, r, a, b, h); },
                       [c](const DRay& r, double a, double b, double g) { return cylinderOracle(c, r, a, b, g); },
                       c.base + c.axis * 500.0f, 500.0f, true, 0.1f};
    const Vec3 side = anyOrthonormal(c.axis), side2 = cross(c.axis, side);
    Tally tally;
    Sampler sampler(37);
    for (int i = 0; i < 2000; ++i) {
        const double angle = std::pow(10.0, sampler.uniform(-4, -2)), phi = sampler.uniform(0, 2 * M_PI);
        const DVec radial = (toD(side) * std::cos(phi) + toD(side2) * std::sin(phi));
        const DVec dir = toD(c.axis) * std::cos(angle) + radial * std::sin(angle);
        const DVec o = toD(c.base) + toD(c.axis) * 1.0 + (toD(side) * 0.05) * sampler.uniform(-1, 1);
        compareOne(sc, {toF(o), toF(dir)}, 0, kInf, tally);
    }
    expectClean(tally, "long pole");
    EXPECT_GT(tally.hits, 1900);
}

}  // namespace
}  // namespace trazo
