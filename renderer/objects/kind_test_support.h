// What the object kinds' tests share (objects/<kind>_test.cpp, every_kind_test.cpp): a double-precision
// oracle of each kind (independent formulations), each kind's float routine and oracle as one ShapeCase,
// random rays near a shape, and the comparison of the routine with the oracle. Host only.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>
#include <string>

#include "core/affine.h"
#include "core/ray.h"
#include "objects/box.h"
#include "objects/cylinder.h"
#include "lights/rectangle.h"
#include "objects/sphere.h"

namespace trazo::kind_test {

inline constexpr float kInf = INFINITY;
inline constexpr float kEps = 1.1920929e-7f;

// ---- Double-precision oracles: independent formulations, on the exact float inputs. ----

struct DVec {
    double x = 0, y = 0, z = 0;
};
inline DVec operator+(DVec a, DVec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline DVec operator-(DVec a, DVec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline DVec operator*(DVec a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(DVec a, DVec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline DVec cross(DVec a, DVec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double length(DVec a) { return std::sqrt(dot(a, a)); }
inline DVec normalize(DVec a) { return a * (1.0 / length(a)); }
inline DVec toD(Vec3 v) { return {v.x, v.y, v.z}; }
inline Vec3 toF(DVec v) { return {float(v.x), float(v.y), float(v.z)}; }

struct DRay {
    DVec o, d;
};
inline DRay toD(const Ray& r) { return {toD(r.origin), toD(r.direction)}; }

struct Reference {
    bool hit = false;
    double t = 0;
    DVec normal;
};

// Keeps the nearest candidate inside the open window.
inline void consider(Reference& best, double t, DVec normal, double tMin, double tMax) {
    if (t > tMin && t < tMax && (!best.hit || t < best.t)) best = {true, t, normalize(normal)};
}

inline Reference sphereOracle(const SphereShape& s, const DRay& ray, double tMin, double tMax, double grow) {
    const double r = s.radius * (1.0 + grow);
    const DVec f = ray.o - toD(s.center);
    const double a = dot(ray.d, ray.d), b = dot(f, ray.d), c = dot(f, f) - r * r;
    const double disc = b * b - a * c;
    Reference best;
    if (disc < 0) return best;
    for (double sign : {-1.0, 1.0}) {
        const double t = (-b + sign * std::sqrt(disc)) / a;
        consider(best, t, f + ray.d * t, tMin, tMax);
    }
    return best;
}

// Möller–Trumbore, two-sided.
inline bool hitTriangle(const DRay& ray, DVec v0, DVec v1, DVec v2, double& t) {
    const DVec e1 = v1 - v0, e2 = v2 - v0;
    const DVec p = cross(ray.d, e2);
    const double det = dot(e1, p);
    if (det == 0) return false;
    const DVec s = ray.o - v0;
    const double u = dot(s, p) / det;
    if (u < 0 || u > 1) return false;
    const DVec q = cross(s, e1);
    const double v = dot(ray.d, q) / det;
    if (v < 0 || u + v > 1) return false;
    t = dot(e2, q) / det;
    return true;
}

// The box the routine sees is objectFromWorld⁻¹(unit cube): invert it in double, take the 8 corners,
// intersect the 12 triangles; the outward normal points away from the centre.
inline Reference boxOracle(const BoxShape& box, const DRay& ray, double tMin, double tMax, double grow) {
    const Affine3& m = box.objectFromWorld;
    const DVec r0 = toD(m.row[0]), r1 = toD(m.row[1]), r2 = toD(m.row[2]);
    const DVec c0 = cross(r1, r2), c1 = cross(r2, r0), c2 = cross(r0, r1);
    const double invDet = 1.0 / dot(r0, c0);
    // Columns of the inverse are the cofactor vectors / det.
    const DVec col[3] = {c0 * invDet, c1 * invDet, c2 * invDet};
    const DVec tObj = toD(m.translation);
    auto toWorld = [&](DVec q) {
        const DVec v = q - tObj;
        return col[0] * v.x + col[1] * v.y + col[2] * v.z;
    };
    const double h = 0.5 * (1.0 + grow);
    DVec corner[8];
    for (int i = 0; i < 8; ++i) corner[i] = toWorld({i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h});
    const DVec centre = toWorld({0, 0, 0});
    // Each face as 4 corner indices around it.
    const int faces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    Reference best;
    for (const auto& face : faces) {
        const DVec v0 = corner[face[0]], v1 = corner[face[1]], v2 = corner[face[2]], v3 = corner[face[3]];
        DVec n = cross(v1 - v0, v3 - v0);
        if (dot(n, v0 - centre) < 0) n = n * -1.0;
        double t;
        if (hitTriangle(ray, v0, v1, v2, t)) consider(best, t, n, tMin, tMax);
        if (hitTriangle(ray, v0, v2, v3, t)) consider(best, t, n, tMin, tMax);
    }
    return best;
}

// In a double orthonormal frame (u, v, w = axis): x² + y² = r² for 0 ≤ z ≤ h, plus the two disks.
inline Reference cylinderOracle(const CylinderShape& c, const DRay& ray, double tMin, double tMax, double grow) {
    const DVec w = normalize(toD(c.axis));
    const DVec u = normalize(cross(std::fabs(w.x) < 0.5 ? DVec{1, 0, 0} : DVec{0, 1, 0}, w));
    const DVec v = cross(w, u);
    const DVec f = ray.o - toD(c.base);
    const DVec o{dot(f, u), dot(f, v), dot(f, w)};
    const DVec d{dot(ray.d, u), dot(ray.d, v), dot(ray.d, w)};
    const double r = c.radius * (1.0 + grow), zLow = -c.height * grow, zHigh = c.height * (1.0 + grow);
    Reference best;
    const double a = d.x * d.x + d.y * d.y, b = o.x * d.x + o.y * d.y, cc = o.x * o.x + o.y * o.y - r * r;
    if (a > 0 && b * b - a * cc >= 0) {
        for (double sign : {-1.0, 1.0}) {
            const double t = (-b + sign * std::sqrt(b * b - a * cc)) / a;
            const double z = o.z + t * d.z;
            if (z >= zLow && z <= zHigh) consider(best, t, u * (o.x + t * d.x) + v * (o.y + t * d.y), tMin, tMax);
        }
    }
    if (d.z != 0) {
        for (double z : {zLow, zHigh}) {
            const double t = (z - o.z) / d.z;
            const double x = o.x + t * d.x, y = o.y + t * d.y;
            if (x * x + y * y <= r * r) consider(best, t, z == zLow ? w * -1.0 : w, tMin, tMax);
        }
    }
    return best;
}

inline Reference rectangleOracle(const RectangleShape& rect, const DRay& ray, double tMin, double tMax, double grow) {
    const DVec c = toD(rect.center), u = toD(rect.halfU) * (1 + grow), v = toD(rect.halfV) * (1 + grow);
    Reference best;
    double t;
    if (hitTriangle(ray, c - u - v, c + u - v, c + u + v, t)) consider(best, t, toD(rect.normal), tMin, tMax);
    if (hitTriangle(ray, c - u - v, c + u + v, c - u + v, t)) consider(best, t, toD(rect.normal), tMin, tMax);
    return best;
}

// ---- One shape, seen through its float routine and its oracle. ----

struct ShapeCase {
    std::function<bool(const Ray&, float, float, ShapeHit&)> intersect;
    // grow > 0 inflates the shape by that fraction of its size (< 0 shrinks it).
    std::function<Reference(const DRay&, double, double, double)> oracle;
    Vec3 center;
    float size;  // bounding radius
    bool solid;
    // The length at which answers are judged: the size, except for a huge shape seen from close.
    float accuracyScale = size;
    bool exitsInward = false;  // a ray spawned into it always leaves through the far side (sphere)
    // Where a hit is, with its error bound: the kind's objectHitPoint (a rectangle, a light, has none).
    std::function<HitPoint(const Ray&, const ShapeHit&)> hitPoint =
        [](const Ray& ray, const ShapeHit& hit) { return rayHitPoint(ray, hit.t, hit.normal); };
};

inline ShapeCase sphereCase(float scale, Vec3 offset) {
    const SphereShape s{offset + Vec3(0.3f, -0.2f, 0.1f) * scale, 1.0f * scale};
    return {[s](const Ray& r, float a, float b, ShapeHit& h) { return intersectSphere(s, r, a, b, h); },
            [s](const DRay& r, double a, double b, double g) { return sphereOracle(s, r, a, b, g); }, s.center,
            s.radius, true, s.radius, true,
            [s](const Ray& r, const ShapeHit& h) { return objectHitPoint(SceneView{}, s, r, h); }};
}

// A sheared parallelepiped: rotate, scale non-uniformly, rotate again, translate (float, as the reader
// builds it), with objectFromWorld = inverse(worldFromObject).
inline BoxShape makeBox(float scale, Vec3 offset) {
    Affine3 w = makeRotation({0, 1, 1}, 0.4f);
    w = then(w, makeScale(Vec3(1.5f, 0.5f, 2.2f) * scale));
    w = then(w, makeRotation({1, 2, 3}, 0.7f));
    w = then(w, makeTranslation(offset + Vec3(0.3f, -0.2f, 0.1f) * scale));
    return {inverse(w), w};
}

inline ShapeCase boxCase(float scale, Vec3 offset) {
    const BoxShape box = makeBox(scale, offset);
    return {[box](const Ray& r, float a, float b, ShapeHit& h) { return intersectBox(box, r, a, b, h); },
            [box](const DRay& r, double a, double b, double g) { return boxOracle(box, r, a, b, g); },
            box.worldFromObject.translation, 1.4f * scale, true, 1.4f * scale, false,
            [box](const Ray& r, const ShapeHit& h) { return objectHitPoint(SceneView{}, box, r, h); }};
}

inline CylinderShape makeCylinder(float scale, Vec3 offset) {
    return {offset + Vec3(0.3f, -0.2f, -0.6f) * scale, normalize(Vec3(1.0f, 2.0f, -0.5f)), 1.7f * scale, 0.6f * scale};
}

inline ShapeCase cylinderCase(float scale, Vec3 offset) {
    const CylinderShape c = makeCylinder(scale, offset);
    return {[c](const Ray& r, float a, float b, ShapeHit& h) { return intersectCylinder(c, r, a, b, h); },
            [c](const DRay& r, double a, double b, double g) { return cylinderOracle(c, r, a, b, g); },
            c.base + c.axis * (0.5f * c.height), 1.05f * scale, true, 1.05f * scale, false,
            [c](const Ray& r, const ShapeHit& h) { return objectHitPoint(SceneView{}, c, r, h); }};
}

inline RectangleShape makeRectangle(float scale, Vec3 offset) {
    const Vec3 n = normalize(Vec3(0.2f, -1.0f, 0.3f));
    const Vec3 u = normalize(cross(Vec3(0, 1, 0), n) * -1.0f);
    const Vec3 v = cross(n, u);
    return {offset + Vec3(0.1f, 0.4f, -0.2f) * scale, u * (0.8f * scale), v * (0.5f * scale), n};
}

inline ShapeCase rectangleCase(float scale, Vec3 offset) {
    const RectangleShape rect = makeRectangle(scale, offset);
    return {[rect](const Ray& r, float a, float b, ShapeHit& h) { return intersectRectangle(rect, r, a, b, h); },
            [rect](const DRay& r, double a, double b, double g) { return rectangleOracle(rect, r, a, b, g); },
            rect.center, 0.95f * scale, false};
}

// ---- Random rays. ----

struct Sampler {
    std::mt19937 rng;
    explicit Sampler(unsigned seed) : rng(seed) {}
    double uniform(double a = 0, double b = 1) { return std::uniform_real_distribution<double>(a, b)(rng); }
    DVec unitVector() {
        const double z = uniform(-1, 1), phi = uniform(0, 2 * M_PI), s = std::sqrt(1 - z * z);
        return {s * std::cos(phi), s * std::sin(phi), z};
    }
    DVec inBall() { return unitVector() * std::cbrt(uniform()); }

    // Origin within 4 bounding radii of the shape, aimed at a point near it; length not unit.
    Ray rayNear(const ShapeCase& sc, double minDistance = 0.0) {
        for (;;) {
            const DVec o = toD(sc.center) + unitVector() * (sc.size * uniform(minDistance, 4.0));
            const DVec target = toD(sc.center) + inBall() * (1.2 * sc.size);
            if (length(target - o) < 0.05 * sc.size) continue;
            const double lengthScale = std::exp(uniform(std::log(0.25), std::log(4.0)));
            return {toF(o), toF(normalize(target - o) * lengthScale)};
        }
    }

    // A direction on n's side: mostly uniform, a third of them grazing (cosine down to 1e-6).
    Vec3 onSide(Vec3 nF) {
        const DVec n = normalize(toD(nF));
        const DVec t = normalize(cross(std::fabs(n.x) < 0.5 ? DVec{1, 0, 0} : DVec{0, 1, 0}, n));
        const DVec b = cross(n, t);
        for (;;) {
            const double cosine = uniform() < 0.33 ? std::pow(10.0, uniform(-6, -2)) : uniform(1e-6, 1);
            const double phi = uniform(0, 2 * M_PI), sine = std::sqrt(1 - cosine * cosine);
            const Vec3 d = toF(n * cosine + (t * std::cos(phi) + b * std::sin(phi)) * sine);
            if (dot(d, nF) > 0.0f) return d;  // offsetRayOrigin decides the side in float
        }
    }
};

inline std::string describe(const Ray& r) {
    std::ostringstream s;
    s.precision(9);
    s << "o=(" << r.origin.x << ", " << r.origin.y << ", " << r.origin.z << ") d=(" << r.direction.x << ", "
      << r.direction.y << ", " << r.direction.z << ")";
    return s.str();
}

// ---- Comparing the float routine with the oracle. ----

// Rays within this fraction of the accuracy scale of the silhouette (or of the window ends) are
// ambiguous: float inputs rounded by far less than that could flip them.
inline constexpr double kGrow = 1e-5;

struct Tally {
    int rays = 0, hits = 0, ambiguous = 0, failures = 0;
    std::string firstFailure;
    void fail(const std::string& what) {
        if (failures++ == 0) firstFailure = what;
    }
};

// Same decision as the oracle unless the ray is ambiguous (kGrow); t within relative 1e-4 (of t, or
// of the accuracy scale in t units for origins close to the surface), and the normal within 1e-5,
// both widened only by how much the answer moves when the shape grows by kGrow (near a silhouette,
// an edge, or along a grazing chord) and, with `coordinateSlack`, by the error bound of core/ray.h
// (the float coordinates themselves are no better than that: a unit shape at 1e4).
inline void compareOne(const ShapeCase& sc, const Ray& ray, float tMin, float tMax, Tally& tally,
                       ShapeHit* out = nullptr, bool coordinateSlack = false) {
    ++tally.rays;
    ShapeHit h{};
    const bool got = sc.intersect(ray, tMin, tMax, h);
    if (out) *out = got ? h : ShapeHit{-1.0f, {}, 0, 0.0f, 0.0f};
    const DRay dr = toD(ray);
    // With coordinate slack, a decision is also ambiguous within 16 ulps of the coordinates (a quarter
    // of ray.h's bound): a box's object-space origin, 1e4 sizes from the world origin, is no better.
    const double coordinateBand = coordinateSlack ? length(toD(hitPointError(ray, 0.0f))) / 4 : 0.0;
    const double grow = (kGrow * sc.accuracyScale + coordinateBand) / sc.size;
    const Reference ref = sc.oracle(dr, tMin, tMax, 0.0);
    const Reference grown = sc.oracle(dr, tMin, tMax, grow), shrunk = sc.oracle(dr, tMin, tMax, -grow);
    const bool bothVariantsHit = grown.hit && shrunk.hit;
    if (got != ref.hit || grown.hit != shrunk.hit) {
        if (grown.hit != shrunk.hit) ++tally.ambiguous;
        else tally.fail("decision: float " + std::to_string(got) + " oracle " + std::to_string(ref.hit) + " " + describe(ray));
        return;
    }
    if (!got) return;
    ++tally.hits;
    const double dLength = length(dr.d);
    double tTolerance = 1e-4 * std::max(ref.t, sc.accuracyScale / dLength);
    double nTolerance = 1e-5;
    if (coordinateSlack) {
        const double bound = length(toD(hitPointError(ray, float(ref.t))));
        tTolerance = std::max(tTolerance, bound / dLength);
        nTolerance = std::max(nTolerance, 2 * bound / sc.accuracyScale);
    }
    if (bothVariantsHit) {
        tTolerance = std::max(tTolerance, std::fabs(grown.t - shrunk.t));
        nTolerance = std::max(nTolerance, length(grown.normal - shrunk.normal));
    }
    const double tError = std::fabs(h.t - ref.t);
    double nError = length(toD(h.normal) - ref.normal);
    // At an edge or a rim either face's normal is right: the grown and shrunk shapes show both.
    if (bothVariantsHit) {
        const double nearestVariant =
            std::min(length(toD(h.normal) - grown.normal), length(toD(h.normal) - shrunk.normal));
        if (nearestVariant <= 1e-5) nError = nearestVariant;
    }
    if (tError > tTolerance || nError > nTolerance || std::fabs(length(toD(h.normal)) - 1) > 1e-6) {
        std::ostringstream s;
        s.precision(9);
        s << "t " << h.t << " vs " << ref.t << " (tol " << tTolerance << "), normal error " << nError << " (tol "
          << nTolerance << ") " << describe(ray);
        tally.fail(s.str());
    }
}

inline void expectClean(const Tally& t, const std::string& label) {
    EXPECT_EQ(t.failures, 0) << label << ": " << t.failures << " of " << t.rays << "; first: " << t.firstFailure;
    EXPECT_LE(t.ambiguous, t.rays / 100) << label << ": too many rays at the silhouette to mean anything";
}

// ---- Exact answers: helpers. ----

inline ShapeHit expectHit(bool got, const ShapeHit& h) {
    EXPECT_TRUE(got);
    return got ? h : ShapeHit{NAN, {NAN, NAN, NAN}, 0, 0.0f, 0.0f};
}
// t to a few ulps of the scale of the configuration.
inline void expectT(float t, double want, double scale, double ulps = 4) { EXPECT_NEAR(t, want, ulps * kEps * scale); }
inline void expectNormal(Vec3 n, Vec3 want, double tolerance = 4 * kEps) {
    EXPECT_NEAR(n.x, want.x, tolerance);
    EXPECT_NEAR(n.y, want.y, tolerance);
    EXPECT_NEAR(n.z, want.z, tolerance);
}

}  // namespace trazo::kind_test
