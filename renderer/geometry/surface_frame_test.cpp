// uv mappings of the analytic shapes: known points, continuity of u·v, and unmirrored frames
// (tangent × bitangent = outward normal) everywhere.
#include "geometry/surface_frame.h"

#include <gtest/gtest.h>

#include <random>

#include "objects/box.h"
#include "objects/cylinder.h"
#include "objects/sphere.h"

namespace trazo {
namespace {

TEST(SurfaceFrame, SphereKnownPoints) {
    const SphereShape s{Vec3(1, 2, 3), 2.0f};
    const SurfaceFrame east = sphereFrame(s, Vec3(3, 2, 3));  // +X: u = 0, equator
    EXPECT_NEAR(east.u, 0.0f, 1e-6f);
    EXPECT_NEAR(east.v, 0.5f, 1e-6f);
    const SurfaceFrame front = sphereFrame(s, Vec3(1, 2, 1));  // −Z: a quarter turn (φ = atan2(−z, x) = π/2)
    EXPECT_NEAR(front.u, 0.25f, 1e-6f);
    EXPECT_NEAR(sphereFrame(s, Vec3(1, 4, 3)).v, 1.0f, 1e-6f);  // north pole
    EXPECT_NEAR(sphereFrame(s, Vec3(1, 0, 3)).v, 0.0f, 1e-6f);  // south pole
}

TEST(SurfaceFrame, BoxFacesMapToTheUnitSquare) {
    const BoxShape unit{Affine3{}, Affine3{}};
    const SurfaceFrame front = boxFrame(unit, Vec3(0.25f, -0.25f, 0.5f));  // +Z face: u = x + ½, v = y + ½
    EXPECT_NEAR(front.u, 0.75f, 1e-6f);
    EXPECT_NEAR(front.v, 0.25f, 1e-6f);
    const SurfaceFrame top = boxFrame(unit, Vec3(0.25f, 0.5f, -0.5f));  // top: u = x + ½, v = −z + ½
    EXPECT_NEAR(top.u, 0.75f, 1e-6f);
    EXPECT_NEAR(top.v, 1.0f, 1e-6f);
}

TEST(SurfaceFrame, CylinderSideAndCaps) {
    const CylinderShape c{Vec3(0, 0, 0), Vec3(0, 1, 0), 4.0f, 1.0f};
    const Vec3 side(anyOrthonormal(c.axis));  // φ = 0 by construction
    const SurfaceFrame f = cylinderFrame(c, side + Vec3(0, 1, 0), side);
    EXPECT_NEAR(f.u, 0.0f, 1e-6f);
    EXPECT_NEAR(f.v, 0.25f, 1e-6f);
    const SurfaceFrame capCentre = cylinderFrame(c, Vec3(0, 4, 0), Vec3(0, 1, 0));
    EXPECT_NEAR(capCentre.u, 0.5f, 1e-6f);
    EXPECT_NEAR(capCentre.v, 0.5f, 1e-6f);
}

// For random rays hitting each shape: the frame is unit, tangent to the surface, unmirrored, and uv ∈ [0,1].
TEST(SurfaceFrame, FramesAreUnmirroredTangentFrames) {
    std::mt19937 gen(7);
    std::uniform_real_distribution<float> U(-1.0f, 1.0f);
    const SphereShape sphere{Vec3(0.3f, -0.2f, 0.1f), 1.3f};
    const BoxShape box{inverse(then(makeScale(Vec3(2, 1, 3)), makeRotation(normalize(Vec3(1, 2, 3)), 0.7f))),
                       then(makeScale(Vec3(2, 1, 3)), makeRotation(normalize(Vec3(1, 2, 3)), 0.7f))};
    const CylinderShape cyl{Vec3(0, -1, 0), normalize(Vec3(0.3f, 1, 0.2f)), 2.0f, 0.8f};
    int checked = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 origin = normalize(Vec3(U(gen), U(gen), U(gen))) * 10.0f;
        const Vec3 target(U(gen), U(gen), U(gen));
        const Ray ray{origin, normalize(target - origin)};
        ShapeHit hit;
        SurfaceFrame f;
        const int shape = i % 3;
        if (shape == 0 && intersectSphere(sphere, ray, 0.0f, INFINITY, hit)) f = sphereFrame(sphere, pointAt(ray, hit.t));
        else if (shape == 1 && intersectBox(box, ray, 0.0f, INFINITY, hit)) f = boxFrame(box, pointAt(ray, hit.t));
        else if (shape == 2 && intersectCylinder(cyl, ray, 0.0f, INFINITY, hit))
            f = cylinderFrame(cyl, pointAt(ray, hit.t), hit.normal);
        else continue;
        ++checked;
        EXPECT_NEAR(length(f.tangent), 1.0f, 1e-4f);
        EXPECT_NEAR(length(f.bitangent), 1.0f, 1e-4f);
        EXPECT_NEAR(dot(f.tangent, hit.normal), 0.0f, 2e-3f);
        EXPECT_NEAR(dot(f.bitangent, hit.normal), 0.0f, 2e-3f);
        // Unmirrored: (tangent × bitangent) points outwards (boxes may shear, so only the side is exact).
        EXPECT_GT(dot(cross(f.tangent, f.bitangent), hit.normal), 0.3f) << "shape " << shape;
        EXPECT_GE(f.u, -1e-4f);
        EXPECT_LE(f.u, 1.0f + 1e-4f);
        EXPECT_GE(f.v, -1e-4f);
        EXPECT_LE(f.v, 1.0f + 1e-4f);
    }
    EXPECT_GT(checked, 1000);
}

}  // namespace
}  // namespace trazo
