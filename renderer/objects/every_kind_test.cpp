// Tests (host) run on every kind of kShapes: random rays against the oracle, grazing rays, scale invariance, and
// rays spawned from a hit (offsetRayOrigin with the kind's objectHitPoint) never re-hitting their surface.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>

#include "core/affine.h"
#include "core/ray.h"
#include "objects/box.h"
#include "objects/kind_test_support.h"
#include "objects/sphere.h"

namespace trazo {
namespace {

using namespace kind_test;

const Vec3 kFarDirection{0.6f, -0.48f, 0.64f};  // a unit vector with no small component

using CaseFactory = ShapeCase (*)(float, Vec3);
struct NamedFactory {
    const char* name;
    CaseFactory make;
};
const NamedFactory kShapes[] = {
    {"sphere", sphereCase}, {"box", boxCase}, {"cylinder", cylinderCase}, {"rectangle", rectangleCase}};

// ---- Random rays from outside and inside: each kind against its oracle (the rectangle: its two triangles). ----

struct RandomRays {
    NamedFactory shape;
    unsigned seed;
    int minHits;
    bool windowed;  // each ray again with a window (tMin, tMax) that may cut the near root
};

class IntersectRandomRays : public ::testing::TestWithParam<RandomRays> {};

TEST_P(IntersectRandomRays, MatchTheOracle) {
    const RandomRays& c = GetParam();
    Tally tally;
    Sampler sampler(c.seed);
    const ShapeCase sc = c.shape.make(1.0f, {0, 0, 0});
    for (int i = 0; i < 5000; ++i) {
        const Ray ray = sampler.rayNear(sc);
        compareOne(sc, ray, 0, kInf, tally);
        if (c.windowed) compareOne(sc, ray, float(sampler.uniform(0, 3)), float(sampler.uniform(3, 8)), tally);
    }
    expectClean(tally, c.shape.name);
    EXPECT_GT(tally.hits, c.minHits);
}

INSTANTIATE_TEST_SUITE_P(Kinds, IntersectRandomRays,
                         ::testing::Values(RandomRays{{"sphere", sphereCase}, 19, 2000, true},
                                           RandomRays{{"box", boxCase}, 11, 1000, false},
                                           RandomRays{{"cylinder", cylinderCase}, 13, 1000, false},
                                           RandomRays{{"rectangle", rectangleCase}, 17, 500, false}),
                         [](const auto& info) { return std::string(info.param.shape.name); });

// ---- Grazing: rays skimming each surface, just outside or just inside it. ----

TEST(IntersectGrazing, RaysSkimmingEachSurfaceAgreeWithTheOracle) {
    // From a random surface point p (normal n, from the oracle), a ray along a tangent at height
    // ±10^[-6, -2] sizes over p: a tangent ray to a sphere or cylinder side, one along a box face or a
    // cap. Those within kGrow of the silhouette may go either way; all others must agree.
    for (const NamedFactory& shape : kShapes) {
        const ShapeCase sc = shape.make(1.0f, {0, 0, 0});
        if (!sc.solid) continue;
        Sampler sampler(41);
        Tally tally;
        for (int i = 0; i < 3000; ++i) {
            const Ray probe = sampler.rayNear(sc, 1.5);
            const Reference surface = sc.oracle(toD(probe), 0, kInf, 0);
            if (!surface.hit) continue;
            const DVec p = toD(probe.origin) + toD(probe.direction) * surface.t, n = surface.normal;
            const DVec tangent = normalize(cross(n, sampler.unitVector()));
            const double height = (sampler.uniform() < 0.5 ? -1 : 1) * std::pow(10.0, sampler.uniform(-6, -2)) * sc.size;
            compareOne(sc, {toF(p + n * height - tangent * (2.0 * sc.size)), toF(tangent)}, 0, kInf, tally);
        }
        EXPECT_EQ(tally.failures, 0) << shape.name << ": " << tally.failures << " of " << tally.rays
                                     << "; first: " << tally.firstFailure;
        EXPECT_GT(tally.rays, 1000) << shape.name;
        EXPECT_LT(tally.ambiguous, tally.rays / 2) << shape.name;
    }
}

// ---- Scale invariance: the same scene at 1e-4 and 1e4 gives the same relative answers. ----

TEST(IntersectScale, SameRelativeAnswersAtTinyAndHugeScales) {
    for (const NamedFactory& shape : kShapes) {
        const ShapeCase unit = shape.make(1.0f, {0, 0, 0});
        for (float k : {1e-4f, 1e4f}) {
            const ShapeCase scaled = shape.make(k, {0, 0, 0});
            Sampler sampler(23);
            Tally unitTally, scaledTally;
            int mismatches = 0;
            std::string first;
            for (int i = 0; i < 3000; ++i) {
                const Ray ray = sampler.rayNear(unit);
                const Ray rayK{ray.origin * k, ray.direction};  // same directions: t scales by k
                ShapeHit h1, hk;
                compareOne(unit, ray, 0, kInf, unitTally, &h1);
                compareOne(scaled, rayK, 0, kInf, scaledTally, &hk);
                const DRay dr = toD(ray);
                const Reference grown = unit.oracle(dr, 0, kInf, kGrow), shrunk = unit.oracle(dr, 0, kInf, -kGrow);
                if (grown.hit != shrunk.hit) continue;
                if (!grown.hit) {
                    if (h1.t >= 0 || hk.t >= 0) ++mismatches;
                    continue;
                }
                const double tTolerance =
                    std::max(2e-5 * std::max<double>(h1.t, unit.size / length(dr.d)), std::fabs(grown.t - shrunk.t));
                const double nTolerance = std::max(2e-5, length(grown.normal - shrunk.normal));
                if (h1.t < 0 || hk.t < 0 || std::fabs(hk.t / k - h1.t) > tTolerance ||
                    length(toD(hk.normal) - toD(h1.normal)) > nTolerance) {
                    if (mismatches++ == 0) first = describe(ray) + " t " + std::to_string(h1.t) + " vs " + std::to_string(hk.t / k);
                }
            }
            const std::string label = std::string(shape.name) + " at scale " + std::to_string(k);
            expectClean(unitTally, label + " (unit)");
            expectClean(scaledTally, label);
            EXPECT_EQ(mismatches, 0) << label << ": first " << first;
        }
    }
}

// ---- Self-intersection: rays spawned with offsetRayOrigin never come back to their surface. ----

struct SelfTally {
    int hits = 0, reHits = 0, inward = 0, inwardWrong = 0;
    std::string firstReHit, firstInwardWrong;
};

// From a random hit p: a ray leaving on the outer side (for the rectangle: either side) must not hit
// the shape again at t > 0; one leaving into a solid must hit its far side, as the oracle says.
void spawnFromHits(const ShapeCase& sc, Sampler& sampler, int count, SelfTally& tally,
                   const std::function<Ray()>& makeRay) {
    for (int i = 0; i < count; ++i) {
        const Ray ray = makeRay();
        ShapeHit h;
        if (!sc.intersect(ray, 0, kInf, h)) continue;
        ++tally.hits;
        const HitPoint at = sc.hitPoint(ray, h);
        const Vec3 p = at.p;
        h.normal = at.normal;
        Vec3 n = h.normal;
        if (!sc.solid && sampler.uniform() < 0.5) n = -n;  // a rectangle is left from either side
        const Vec3 out = sampler.onSide(n);
        const Ray leaving{offsetRayOrigin(p, at.offset, h.normal, out), out};
        ShapeHit again;
        if (sc.intersect(leaving, 0, kInf, again)) {
            if (tally.reHits++ == 0) {
                std::ostringstream s;
                s.precision(9);
                s << "from " << describe(ray) << " t=" << h.t << " p=(" << p.x << ", " << p.y << ", " << p.z
                  << ") offset=" << at.offset << " n=(" << n.x << ", " << n.y
                  << ", " << n.z << "); spawned " << describe(leaving) << " re-hit at t=" << again.t;
                tally.firstReHit = s.str();
            }
        }
        if (!sc.solid) continue;
        // Into the solid: the oracle's answer from the spawned origin. For a sphere that must be the far
        // side (an exit); a box or cylinder hit beside an edge may legitimately re-enter the next face.
        ++tally.inward;
        const Vec3 in = sampler.onSide(-h.normal);
        const Ray entering{offsetRayOrigin(p, at.offset, h.normal, in), in};
        Tally inward;
        ShapeHit far;
        compareOne(sc, entering, 0, kInf, inward, &far, true);
        const bool exits = far.t > 0 && dot(far.normal, in) > 0;
        if (inward.failures > 0 || (sc.exitsInward && !exits)) {
            if (tally.inwardWrong++ == 0) {
                std::ostringstream s;
                s.precision(9);
                s << "from hit t=" << h.t << " of " << describe(ray) << ": " << describe(entering) << " got t=" << far.t
                  << " n=(" << far.normal.x << ", " << far.normal.y << ", " << far.normal.z << ") " << inward.firstFailure;
                tally.firstInwardWrong = s.str();
            }
        }
    }
}

void expectNoSelfIntersection(const SelfTally& tally, const std::string& label, int minimumHits) {
    EXPECT_GE(tally.hits, minimumHits) << label;
    EXPECT_EQ(tally.reHits, 0) << label << ": " << tally.reHits << " of " << tally.hits
                               << " spawned rays re-hit; first: " << tally.firstReHit;
    EXPECT_EQ(tally.inwardWrong, 0) << label << ": " << tally.inwardWrong << " of " << tally.inward
                                    << " inward rays missed the far side; first: " << tally.firstInwardWrong;
}

TEST(IntersectSelf, SpawnedRaysNeverReHitTheirSurface) {
    // Each scale near the origin and 1e4 sizes away from it (the shape at 1e4 for scale 1, 1e7 for
    // 1e3; a 1e-3 shape at 1e4 would be a single float ulp wide).
    for (const NamedFactory& shape : kShapes) {
        for (float scale : {1e-3f, 1.0f, 1e3f}) {
            for (float far : {0.0f, 1e4f}) {
                const ShapeCase sc = shape.make(scale, kFarDirection * (far * scale));
                Sampler sampler(29);
                SelfTally tally;
                // Primary rays from outside and, for solids, from inside (exit hits).
                spawnFromHits(sc, sampler, 3000, tally, [&] { return sampler.rayNear(sc, 1.5); });
                if (sc.solid) {
                    spawnFromHits(sc, sampler, 1000, tally, [&] {
                        const Vec3 o = toF(toD(sc.center) + sampler.inBall() * (0.25 * sc.size));
                        return Ray{o, toF(sampler.unitVector())};
                    });
                }
                std::ostringstream label;
                label << shape.name << " scale " << scale << " offset " << far * scale;
                expectNoSelfIntersection(tally, label.str(), sc.solid ? 1000 : 600);
            }
        }
    }
}

TEST(IntersectSelf, SpawnedRaysFromFarAwayNeitherReHitNorStepOver) {
    // The camera 1e3 and 1e4 sizes away from each shape, at the origin and 1e3 sizes from it: the hit point o + t·d
    // is off the surface by ulps of the camera's distance, the kind's own hit point by ulps of the shape's. A ray
    // spawned outwards must not come back; one spawned inwards must find the far side where the oracle does.
    for (const NamedFactory& shape : kShapes) {
        if (std::string(shape.name) == "rectangle") continue;  // a light: nothing leaves it
        for (float offset : {0.0f, 1e3f}) {
            for (double distance : {1e3, 1e4}) {
                const ShapeCase sc = shape.make(1.0f, kFarDirection * offset);
                Sampler sampler(37);
                SelfTally tally;
                spawnFromHits(sc, sampler, 2000, tally, [&] {
                    const DVec o = toD(sc.center) + sampler.unitVector() * (sc.size * distance);
                    const DVec target = toD(sc.center) + sampler.inBall() * (1.2 * sc.size);
                    return Ray{toF(o), toF(normalize(target - o))};
                });
                std::ostringstream label;
                label << shape.name << " at " << offset << " seen from " << distance << " away";
                expectNoSelfIntersection(tally, label.str(), 600);
            }
        }
    }
}

TEST(IntersectSelf, ThinSlabSeenFromFarAwayIsCrossedNotSteppedOver) {
    // A pane 0.01 thick (1/200 of its width), turned 45°, seen from 1e3 away: a ray spawned into it from the
    // front face must leave through the back face, at t of about its thickness, never start beyond it.
    Affine3 w = makeScale(Vec3(2.0f, 2.0f, 0.01f));
    w = then(w, makeRotation({0, 1, 0}, 0.785398f));
    const BoxShape pane{inverse(w), w};
    Sampler sampler(41);
    int crossed = 0, steppedOver = 0;
    for (int i = 0; i < 2000; ++i) {
        const DVec o = DVec{0.3, 0.2, 1.0} * (1e3 / std::sqrt(1.13)) + sampler.inBall() * 5.0;
        const DVec target = sampler.inBall() * 0.5;
        const Ray ray{toF(o), toF(normalize(target - o))};
        ShapeHit h;
        if (!intersectBox(pane, ray, 0.0f, kInf, h)) continue;
        const HitPoint at = objectHitPoint(SceneView{}, pane, ray, h);
        const Vec3 in = ray.direction;  // straight on, as a ray through glass of index 1
        const Ray inside{offsetRayOrigin(at.p, at.offset, h.normal, in), in};
        ShapeHit back;
        const bool exits = intersectBox(pane, inside, 0.0f, kInf, back) && dot(back.normal, in) > 0.0f &&
                           dot(back.normal, h.normal) < 0.0f;
        ++(exits ? crossed : steppedOver);
    }
    EXPECT_GT(crossed, 1000);
    EXPECT_EQ(steppedOver, 0) << "of " << crossed + steppedOver << " rays into the pane";
}

TEST(IntersectSelf, HugeGroundSphereSeenFromClose) {
    // A ground sphere (the classic r = 1000 at y = −1000, and r = 1e5) with the camera a few units away:
    // the hit points are small numbers while the sphere's are large.
    for (float r : {1e3f, 1e5f}) {
        const SphereShape s{{0, -r, 0}, r};
        const ShapeCase sc{[s](const Ray& ray, float a, float b, ShapeHit& h) { return intersectSphere(s, ray, a, b, h); },
                           [s](const DRay& ray, double a, double b, double g) { return sphereOracle(s, ray, a, b, g); },
                           s.center, s.radius, true, 10.0f, true};
        Sampler sampler(31);
        SelfTally tally;
        spawnFromHits(sc, sampler, 3000, tally, [&] {
            const DVec o{sampler.uniform(-5, 5), sampler.uniform(0.5, 5), sampler.uniform(5, 15)};
            const DVec target{sampler.uniform(-10, 10), 0, sampler.uniform(-10, 10)};
            return Ray{toF(o), toF(normalize(target - o))};
        });
        // Grazing views towards the horizon (slopes down to ~1e-4), up to 200 units away.
        spawnFromHits(sc, sampler, 3000, tally, [&] {
            const DVec o{sampler.uniform(-5, 5), sampler.uniform(0.01, 0.3), sampler.uniform(5, 15)};
            const double x = sampler.uniform(-50, 50), z = -sampler.uniform(20, 200);
            const DVec target{x, std::sqrt(double(r) * r - x * x - z * z) - r - 1e-3, z};  // just below the top
            return Ray{toF(o), toF(normalize(target - o))};
        });
        expectNoSelfIntersection(tally, "ground sphere r = " + std::to_string(r), 5000);
    }
}

}  // namespace
}  // namespace trazo
