// Tests (host) of intersectSphere against closed forms and its double-precision oracle (kind_test_support.h).
#include <gtest/gtest.h>

#include <cmath>

#include "objects/kind_test_support.h"
#include "objects/sphere.h"

namespace trazo {
namespace {

using namespace kind_test;

TEST(IntersectSphere, HitFromOutsideIsExact) {
    const SphereShape s{{1, 2, 3}, 2};
    ShapeHit h;
    h = expectHit(intersectSphere(s, {{1, 2, 13}, {0, 0, -1}}, 0, kInf, h), h);
    expectT(h.t, 8, 13);
    expectNormal(h.normal, {0, 0, 1});
    // Off-centre: enters at (1 + 1.2, 2, 3 + 1.6): t = 13 − 4.6, normal (0.6, 0, 0.8).
    h = expectHit(intersectSphere(s, {{2.2f, 2, 13}, {0, 0, -1}}, 0, kInf, h), h);
    expectT(h.t, 8.4, 13);
    expectNormal(h.normal, {0.6f, 0, 0.8f});
}

TEST(IntersectSphere, TIsInUnitsOfTheDirection) {
    const SphereShape s{{0, 0, 0}, 1};
    ShapeHit h;
    h = expectHit(intersectSphere(s, {{0, 0, 9}, {0, 0, -4}}, 0, kInf, h), h);
    expectT(h.t, 2, 9);
    expectNormal(h.normal, {0, 0, 1});
    h = expectHit(intersectSphere(s, {{0, 0, 9}, {0, 0, -0.125f}}, 0, kInf, h), h);
    expectT(h.t, 64, 72);
}

TEST(IntersectSphere, Misses) {
    const SphereShape s{{0, 0, 0}, 1};
    ShapeHit h;
    EXPECT_FALSE(intersectSphere(s, {{1.5f, 0, 5}, {0, 0, -1}}, 0, kInf, h));  // passes beside
    EXPECT_FALSE(intersectSphere(s, {{0, 0, 5}, {0, 0, 1}}, 0, kInf, h));      // sphere behind
    EXPECT_FALSE(intersectSphere(s, {{0, 0, 5}, {0, 1, 0}}, 0, kInf, h));      // perpendicular, away
}

TEST(IntersectSphere, TangentRay) {
    const SphereShape s{{0, 0, 0}, 1};
    ShapeHit h;
    // Exactly tangent: the closed sphere is touched at (0, 1, 0), t = 5.
    h = expectHit(intersectSphere(s, {{-5, 1, 0}, {1, 0, 0}}, 0, kInf, h), h);
    expectT(h.t, 5, 5);
    expectNormal(h.normal, {0, 1, 0});
    EXPECT_FALSE(intersectSphere(s, {{-5, 1.000001f, 0}, {1, 0, 0}}, 0, kInf, h));
    // Just inside the silhouette: two roots 5 ∓ √(1 − y²), the nearer taken.
    const float y = 0.999999f;
    h = expectHit(intersectSphere(s, {{-5, y, 0}, {1, 0, 0}}, 0, kInf, h), h);
    const double halfChord = std::sqrt(1.0 - double(y) * y);
    EXPECT_NEAR(h.t, 5 - halfChord, 1e-6);
    EXPECT_NEAR(h.normal.x, -halfChord, 1e-5);
}

TEST(IntersectSphere, OriginInsideHitsExitWithOutwardNormal) {
    const SphereShape s{{1, 1, 1}, 2};
    ShapeHit h;
    h = expectHit(intersectSphere(s, {{1, 1, 1}, {0, 0, 1}}, 0, kInf, h), h);
    expectT(h.t, 2, 3);
    expectNormal(h.normal, {0, 0, 1});
    h = expectHit(intersectSphere(s, {{1, 1, 2}, {0, -3, 0}}, 0, kInf, h), h);  // exit at (1, 1 − √3, 2)
    expectT(h.t, std::sqrt(3.0) / 3, 3);
    expectNormal(h.normal, {0, -float(std::sqrt(0.75)), 0.5f});
}

TEST(IntersectSphere, WindowSelectsTheRoot) {
    const SphereShape s{{0, 0, 0}, 1};
    const Ray ray{{0, 0, 5}, {0, 0, -1}};  // roots 4 and 6
    ShapeHit h;
    h = expectHit(intersectSphere(s, ray, 4.5f, kInf, h), h);  // near root cut: the far one, normal −z
    expectT(h.t, 6, 6);
    expectNormal(h.normal, {0, 0, -1});
    EXPECT_FALSE(intersectSphere(s, ray, 0, 3.9f, h));
    EXPECT_FALSE(intersectSphere(s, ray, 6.1f, kInf, h));
    EXPECT_FALSE(intersectSphere(s, ray, 0, 4.0f, h));  // the window is open at both ends
    EXPECT_FALSE(intersectSphere(s, ray, 6.0f, kInf, h));
    h = expectHit(intersectSphere(s, ray, 0, 4.0001f, h), h);
    expectT(h.t, 4, 5);
}

TEST(IntersectSphere, TinySphereFarAway) {
    // r/distance = 1e-5: b² − a·c would lose the discriminant entirely (b² ≈ 1e10, ulp 1024).
    const SphereShape s{{0, 0, -1e5f}, 1};
    ShapeHit h;
    h = expectHit(intersectSphere(s, {{0, 0, 0}, {0, 0, -1}}, 0, kInf, h), h);
    expectT(h.t, 1e5 - 1, 1e5);
    expectNormal(h.normal, {0, 0, 1});
    EXPECT_FALSE(intersectSphere(s, {{0, 0, 0}, toF(normalize(DVec{1.01, 0, -1e5}))}, 0, kInf, h));
    // Aimed at a point at 0.6 of the radius: the oracle agrees on t and on the normal.
    Tally tally;
    Sampler sampler(7);
    const ShapeCase sc{[s](const Ray& r, float a, float b, ShapeHit& hh) { return intersectSphere(s, r, a, b, hh); },
                       [s](const DRay& r, double a, double b, double g) { return sphereOracle(s, r, a, b, g); },
                       s.center, 1, true};
    for (int i = 0; i < 2000; ++i) {
        const DVec target = toD(s.center) + sampler.inBall() * 1.2;
        const DVec o = sampler.unitVector() * 3.0;
        compareOne(sc, {toF(o), toF(normalize(target - o))}, 0, kInf, tally);
    }
    expectClean(tally, "tiny sphere far away");
    EXPECT_GT(tally.hits, 500);
}

TEST(IntersectSphere, HugeSphereNear) {
    // A ground sphere: the hit is 1 unit away while |f|² − r² cancels down from 1e10.
    const SphereShape s{{0, -1e5f, 0}, 1e5f};
    ShapeHit h;
    h = expectHit(intersectSphere(s, {{0, 1, 0}, {0, -1, 0}}, 0, kInf, h), h);
    expectT(h.t, 1, 1);
    expectNormal(h.normal, {0, 1, 0});
    Tally tally;
    Sampler sampler(8);
    const ShapeCase sc{[s](const Ray& r, float a, float b, ShapeHit& hh) { return intersectSphere(s, r, a, b, hh); },
                       [s](const DRay& r, double a, double b, double g) { return sphereOracle(s, r, a, b, g); },
                       s.center, s.radius, true, 10.0f};
    for (int i = 0; i < 2000; ++i) {
        const DVec o{sampler.uniform(-5, 5), sampler.uniform(0.01, 3), sampler.uniform(-5, 5)};
        const DVec target{sampler.uniform(-10, 10), -0.5, sampler.uniform(-10, 10)};
        compareOne(sc, {toF(o), toF(normalize(target - o))}, 0, kInf, tally);
    }
    expectClean(tally, "huge sphere near");
    EXPECT_EQ(tally.hits, tally.rays);
}

}  // namespace
}  // namespace trazo
