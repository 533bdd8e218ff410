// Tests (host) that the formulas written once over the number type, instantiated for SIMD lanes (LaneOps), give
// their scalar instantiation's bits lane by lane on random inputs: Cook–Torrance, Oren–Nayar, and the sphere, box
// and cylinder tests, with inputs one per lane and shared by all lanes. At this translation unit's lane width; the
// packet tests run every ISA's through the traversals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "core/host_simd.h"

#if TRAZO_HOST_PACKETS
#include "integrator/packets/packet_lanes.h"
#include "shading/cook_torrance.h"
#include "shading/oren_nayar.h"

namespace trazo {
namespace {

using namespace packet_detail;

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Random {
    std::mt19937 rng;
    explicit Random(uint32_t seed) : rng(seed) {}
    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
    Vec3 vector(float e) { return Vec3(uniform(-e, e), uniform(-e, e), uniform(-e, e)); }
    Vec3 unit() {
        for (;;) {
            const Vec3 v = vector(1.0f);
            if (dot(v, v) > 1e-4f) return normalize(v);
        }
    }
    // Some lanes off, now and then.
    uint64_t lanes() { return rng() % 4 == 0 ? rng() & kGroupBits : kGroupBits; }
};

// Lanes of a Vec3 per lane, and back.
struct Vectors {
    alignas(64) float x[kLanes], y[kLanes], z[kLanes];
    void set(int i, Vec3 v) { x[i] = v.x, y[i] = v.y, z[i] = v.z; }
    V3 lanes() const { return {load(x), load(y), load(z)}; }
};
struct Floats {
    alignas(64) float v[kLanes];
    LaneF lanes() const { return load(v); }
};

TEST(LaneOps, CookTorranceIsTheScalarCodeInEveryLane) {
    Random random(1);
    for (int round = 0; round < 20000; ++round) {
        Vectors n, l, v;
        Floats roughness;
        for (int i = 0; i < kLanes; ++i) {
            n.set(i, random.unit()), l.set(i, random.unit()), v.set(i, random.unit());
            roughness.v[i] = round % 7 == 0 ? 0.0f : random.uniform(0.0f, 1.0f);
        }
        const uint64_t live = random.lanes();
        const LaneF own = cookTorranceOf<LaneOps>(n.lanes(), l.lanes(), v.lanes(), roughness.lanes(), laneMask(live));
        const Vec3 n0(n.x[0], n.y[0], n.z[0]), v0(v.x[0], v.y[0], v.z[0]);
        const LaneF shared = cookTorranceOf<LaneOps>(n0, l.lanes(), v0, roughness.v[0], laneMask(live));
        for (int i = 0; i < kLanes; ++i) {
            if (!(live >> i & 1u)) continue;
            const Vec3 li(l.x[i], l.y[i], l.z[i]);
            ASSERT_TRUE(sameBits(own[i], evalCookTorrance(Vec3(n.x[i], n.y[i], n.z[i]), li,
                                                          Vec3(v.x[i], v.y[i], v.z[i]), roughness.v[i])))
                << round << " lane " << i;
            ASSERT_TRUE(sameBits(shared[i], evalCookTorrance(n0, li, v0, roughness.v[0]))) << round << " lane " << i;
        }
    }
}

TEST(LaneOps, OrenNayarIsTheScalarCodeInEveryLane) {
    Random random(2);
    for (int round = 0; round < 20000; ++round) {
        Vectors n, l, v;
        Floats sigma;
        for (int i = 0; i < kLanes; ++i) {
            const Vec3 ni = random.unit();
            n.set(i, ni), l.set(i, random.unit());
            v.set(i, round % 11 == 0 ? ni : random.unit());  // V ∥ N: no tangent part
            sigma.v[i] = round % 5 == 0 ? 0.0f : random.uniform(0.0f, 1.0f);
        }
        const LaneF own = evalOrenNayarOf<LaneOps>(orenNayarViewOf<LaneOps>(n.lanes(), v.lanes(), sigma.lanes()),
                                                   n.lanes(), l.lanes());
        const Vec3 n0(n.x[0], n.y[0], n.z[0]), v0(v.x[0], v.y[0], v.z[0]);
        const OrenNayarView view0 = orenNayarView(n0, v0, sigma.v[0]);
        const LaneF shared = evalOrenNayarOf<LaneOps>(view0, n0, l.lanes());
        for (int i = 0; i < kLanes; ++i) {
            const Vec3 ni(n.x[i], n.y[i], n.z[i]), li(l.x[i], l.y[i], l.z[i]);
            ASSERT_TRUE(sameBits(own[i], evalOrenNayar(ni, li, Vec3(v.x[i], v.y[i], v.z[i]), sigma.v[i])))
                << round << " lane " << i;
            ASSERT_TRUE(sameBits(shared[i], evalOrenNayar(view0, n0, li))) << round << " lane " << i;
        }
    }
}

// A group of rays: from one origin or each from its own, towards points near `target` (some far off), and
// some along axes with a signed zero; tMax infinite or not.
struct Rays {
    Vectors origins, directions;
    Floats tMax;
    Group group() const { return {directions.lanes(), tMax.lanes()}; }
    Ray ray(int i) const {
        return Ray{Vec3(origins.x[i], origins.y[i], origins.z[i]),
                   Vec3(directions.x[i], directions.y[i], directions.z[i])};
    }
};
Rays makeRays(Random& random, Vec3 target, float spread, bool shared) {
    Rays r;
    const Vec3 common = target + random.vector(4.0f * spread);
    for (int i = 0; i < kLanes; ++i) {
        const Vec3 o = shared ? common : target + random.vector(4.0f * spread);
        Vec3 d = target + random.vector(spread) - o;
        if (random.rng() % 8 == 0) {
            d = Vec3(0.0f, -0.0f, 0.0f);
            d[random.rng() % 3] = random.rng() % 2 ? 1.0f : -1.0f;
        }
        r.origins.set(i, o);
        r.directions.set(i, d);
        r.tMax.v[i] = random.rng() % 3 == 0 ? random.uniform(0.0f, 1.5f) : INFINITY;
    }
    return r;
}

// Some windows end exactly at the nearest hit, which the open window (0, tMax) leaves out.
template <class Intersect>
void endSomeWindowsAtTheHit(Random& random, Rays& rays, Intersect intersect) {
    for (int i = 0; i < kLanes; ++i) {
        ShapeHit hit;
        if (random.rng() % 4 == 0 && intersect(rays.ray(i), hit)) rays.tMax.v[i] = hit.t;
    }
}

TEST(LaneOps, SphereHitsAreIntersectSphereInEveryLane) {
    Random random(3);
    for (int round = 0; round < 20000; ++round) {
        const SphereShape s{random.vector(5.0f), random.uniform(0.05f, 3.0f)};
        const bool shared = round % 2 == 0;
        Rays rays = makeRays(random, s.center, s.radius, shared);
        endSomeWindowsAtTheHit(random, rays,
                               [&](const Ray& r, ShapeHit& h) { return intersectSphere(s, r, 0.0f, INFINITY, h); });
        const uint64_t live = random.lanes();
        LaneF tHit;
        V3 normal;
        const uint64_t hits =
            shared ? sphereHits(s, sphereSetupOf<ScalarOps>(s, rays.ray(0).origin), rays.group(), live, tHit, &normal)
                   : sphereHits(s, sphereSetupOf<LaneOps>(s, rays.origins.lanes()), rays.group(), live, tHit, &normal);
        for (int i = 0; i < kLanes; ++i) {
            if (!(live >> i & 1u)) continue;
            ShapeHit want;
            const bool hit = intersectSphere(s, rays.ray(i), 0.0f, rays.tMax.v[i], want);
            ASSERT_EQ(bool(hits >> i & 1u), hit) << round << " lane " << i;
            if (!hit) continue;
            ASSERT_TRUE(sameBits(tHit[i], want.t)) << round << " lane " << i;
            ASSERT_TRUE(sameBits(normal.x[i], want.normal.x) && sameBits(normal.y[i], want.normal.y) &&
                        sameBits(normal.z[i], want.normal.z))
                << round << " lane " << i;
        }
    }
}

TEST(LaneOps, BoxHitsAreIntersectBoxInEveryLane) {
    Random random(4);
    for (int round = 0; round < 20000; ++round) {
        Affine3 m;
        for (int r = 0; r < 3; ++r) m.row[r] = random.vector(2.0f);
        if (round % 3 == 0) m = Affine3{};  // axis-aligned: rays in face planes, along edges
        m.translation = random.vector(5.0f);
        if (!(std::fabs(determinant(m)) > 1e-3f)) continue;
        const BoxShape box{inverse(m), m};
        const bool shared = round % 2 == 0;
        Rays rays = makeRays(random, m.translation, 1.0f, shared);
        endSomeWindowsAtTheHit(random, rays,
                               [&](const Ray& r, ShapeHit& h) { return intersectBox(box, r, 0.0f, INFINITY, h); });
        const uint64_t live = random.lanes();
        LaneF tHit;
        LaneI face;
        const uint64_t hits = shared ? boxHits(box, rays.ray(0).origin, rays.group(), live, tHit, face)
                                     : boxHits(box, rays.origins.lanes(), rays.group(), live, tHit, face);
        for (int i = 0; i < kLanes; ++i) {
            if (!(live >> i & 1u)) continue;
            ShapeHit want;
            const bool hit = intersectBox(box, rays.ray(i), 0.0f, rays.tMax.v[i], want);
            ASSERT_EQ(bool(hits >> i & 1u), hit) << round << " lane " << i;
            if (!hit) continue;
            ASSERT_TRUE(sameBits(tHit[i], want.t)) << round << " lane " << i;
            ASSERT_EQ(uint32_t(face[i]), want.triangle) << round << " lane " << i;
        }
    }
}

TEST(LaneOps, CylinderHitsAreIntersectCylinderInEveryLane) {
    Random random(5);
    for (int round = 0; round < 20000; ++round) {
        const CylinderShape c{random.vector(5.0f), round % 3 == 0 ? Vec3(0.0f, 1.0f, 0.0f) : random.unit(),
                              random.uniform(0.1f, 3.0f), random.uniform(0.05f, 2.0f)};
        const bool shared = round % 2 == 0;
        Rays rays = makeRays(random, c.base + c.axis * (0.5f * c.height), c.height, shared);
        endSomeWindowsAtTheHit(random, rays,
                               [&](const Ray& r, ShapeHit& h) { return intersectCylinder(c, r, 0.0f, INFINITY, h); });
        const uint64_t live = random.lanes();
        LaneF tHit;
        const uint64_t hits = shared ? cylinderHits(c, rays.ray(0).origin, rays.group(), live, tHit)
                                     : cylinderHits(c, rays.origins.lanes(), rays.group(), live, tHit);
        for (int i = 0; i < kLanes; ++i) {
            if (!(live >> i & 1u)) continue;
            ShapeHit want;
            const bool hit = intersectCylinder(c, rays.ray(i), 0.0f, rays.tMax.v[i], want);
            ASSERT_EQ(bool(hits >> i & 1u), hit) << round << " lane " << i;
            if (!hit) continue;
            ASSERT_TRUE(sameBits(tHit[i], want.t)) << round << " lane " << i;
        }
    }
}

}  // namespace
}  // namespace trazo
#endif
