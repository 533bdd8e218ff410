// Refraction against Snell's law, total internal reflection, mirror reflection and the glossy cone.
#include <gtest/gtest.h>

#include <random>

#include "shading/scattering.h"

namespace trazo {
namespace {

TEST(ScatteringRefraction, ObeysSnellsLawInAPlane) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < 10000; ++i) {
        const Vec3 n = normalize(Vec3(u(rng), u(rng), u(rng)));
        Vec3 d = normalize(Vec3(u(rng), u(rng), u(rng)));
        if (dot(d, n) > -0.01f) continue;
        for (float eta : {1.0f / 1.5f, 1.5f, 1.0f / 2.4f}) {
            Vec3 t;
            const float sinI = length(cross(d, n));
            if (!refractDirection(d, n, eta, t)) {
                EXPECT_GT(eta * sinI, 1.0f - 1e-5f);  // TIR only past the critical angle
                continue;
            }
            EXPECT_NEAR(length(t), 1.0f, 1e-5f);
            EXPECT_NEAR(length(cross(t, n)), eta * sinI, 2e-5f);  // n1 sin θ1 = n2 sin θ2
            EXPECT_LT(dot(t, n), 0.0f);                           // continues through the surface
            EXPECT_NEAR(dot(cross(d, n), t), 0.0f, 2e-5f);        // stays in the plane of incidence
        }
    }
}

TEST(ScatteringRefraction, TotalInternalReflectionBeyondTheCriticalAngle) {
    const float n = 1.5f, critical = asinf(1.0f / n);
    const Vec3 normal(0, 0, 1);
    Vec3 t;
    const Vec3 below(sinf(critical - 0.01f), 0, -cosf(critical - 0.01f));
    const Vec3 above(sinf(critical + 0.01f), 0, -cosf(critical + 0.01f));
    EXPECT_TRUE(refractDirection(below, normal, n, t));
    EXPECT_FALSE(refractDirection(above, normal, n, t));
}

TEST(ScatteringRefraction, NormalIncidencePassesStraight) {
    Vec3 t;
    ASSERT_TRUE(refractDirection(Vec3(0, 0, -1), Vec3(0, 0, 1), 1.0f / 1.5f, t));
    EXPECT_NEAR(t.z, -1.0f, 1e-6f);
}

TEST(ScatteringReflection, MirrorKeepsTheAngle) {
    const Vec3 d = normalize(Vec3(1, -2, 0.5f)), n(0, 1, 0);
    const Vec3 r = reflectDirection(d, n);
    EXPECT_NEAR(r.y, -d.y, 1e-6f);
    EXPECT_NEAR(r.x, d.x, 1e-6f);
    EXPECT_NEAR(r.z, d.z, 1e-6f);
}

TEST(ScatteringReflection, ConeDirectionHasThePolarAngleAsked) {
    const Vec3 axis = normalize(Vec3(0.2f, 0.5f, -1.0f));
    for (float theta : {0.0f, 0.1f, 0.5f, 1.2f})
        for (float phi : {0.0f, 1.0f, 4.0f}) {
            const Vec3 d = directionInCone(axis, theta, phi);
            EXPECT_NEAR(length(d), 1.0f, 1e-5f);
            EXPECT_NEAR(acosf(fminf(1.0f, dot(d, axis))), theta, 2e-3f);
        }
}

}  // namespace
}  // namespace trazo
