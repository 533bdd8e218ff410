// Tests (host) of the ray–shape intersection routines against closed forms and double-precision oracles.
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
#include "objects/rectangle.h"
#include "objects/sphere.h"

namespace trazo {
namespace {

constexpr float kInf = INFINITY;
constexpr float kEps = 1.1920929e-7f;

// ---- Double-precision oracles: independent formulations, on the exact float inputs. ----

struct DVec {
    double x = 0, y = 0, z = 0;
};
DVec operator+(DVec a, DVec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
DVec operator-(DVec a, DVec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
DVec operator*(DVec a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(DVec a, DVec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
DVec cross(DVec a, DVec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double length(DVec a) { return std::sqrt(dot(a, a)); }
DVec normalize(DVec a) { return a * (1.0 / length(a)); }
DVec toD(Vec3 v) { return {v.x, v.y, v.z}; }
Vec3 toF(DVec v) { return {float(v.x), float(v.y), float(v.z)}; }

struct DRay {
    DVec o, d;
};
DRay toD(const Ray& r) { return {toD(r.origin), toD(r.direction)}; }

struct Reference {
    bool hit = false;
    double t = 0;
    DVec normal;
};

// Keeps the nearest candidate inside the open window.
void consider(Reference& best, double t, DVec normal, double tMin, double tMax) {
    if (t > tMin && t < tMax && (!best.hit || t < best.t)) best = {true, t, normalize(normal)};
}

Reference sphereOracle(const SphereShape& s, const DRay& ray, double tMin, double tMax, double grow) {
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
bool hitTriangle(const DRay& ray, DVec v0, DVec v1, DVec v2, double& t) {
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
Reference boxOracle(const BoxShape& box, const DRay& ray, double tMin, double tMax, double grow) {
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
Reference cylinderOracle(const CylinderShape& c, const DRay& ray, double tMin, double tMax, double grow) {
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

Reference rectangleOracle(const RectangleShape& rect, const DRay& ray, double tMin, double tMax, double grow) {
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

const Vec3 kFarDirection{0.6f, -0.48f, 0.64f};  // a unit vector with no small component

ShapeCase sphereCase(float scale, Vec3 offset) {
    const SphereShape s{offset + Vec3(0.3f, -0.2f, 0.1f) * scale, 1.0f * scale};
    return {[s](const Ray& r, float a, float b, ShapeHit& h) { return intersectSphere(s, r, a, b, h); },
            [s](const DRay& r, double a, double b, double g) { return sphereOracle(s, r, a, b, g); }, s.center,
            s.radius, true, s.radius, true,
            [s](const Ray& r, const ShapeHit& h) { return objectHitPoint(SceneView{}, s, r, h); }};
}

// A sheared parallelepiped: rotate, scale non-uniformly, rotate again, translate (float, as the reader
// builds it), with objectFromWorld = inverse(worldFromObject).
BoxShape makeBox(float scale, Vec3 offset) {
    Affine3 w = makeRotation({0, 1, 1}, 0.4f);
    w = then(w, makeScale(Vec3(1.5f, 0.5f, 2.2f) * scale));
    w = then(w, makeRotation({1, 2, 3}, 0.7f));
    w = then(w, makeTranslation(offset + Vec3(0.3f, -0.2f, 0.1f) * scale));
    return {inverse(w), w};
}

ShapeCase boxCase(float scale, Vec3 offset) {
    const BoxShape box = makeBox(scale, offset);
    return {[box](const Ray& r, float a, float b, ShapeHit& h) { return intersectBox(box, r, a, b, h); },
            [box](const DRay& r, double a, double b, double g) { return boxOracle(box, r, a, b, g); },
            box.worldFromObject.translation, 1.4f * scale, true, 1.4f * scale, false,
            [box](const Ray& r, const ShapeHit& h) { return objectHitPoint(SceneView{}, box, r, h); }};
}

CylinderShape makeCylinder(float scale, Vec3 offset) {
    return {offset + Vec3(0.3f, -0.2f, -0.6f) * scale, normalize(Vec3(1.0f, 2.0f, -0.5f)), 1.7f * scale, 0.6f * scale};
}

ShapeCase cylinderCase(float scale, Vec3 offset) {
    const CylinderShape c = makeCylinder(scale, offset);
    return {[c](const Ray& r, float a, float b, ShapeHit& h) { return intersectCylinder(c, r, a, b, h); },
            [c](const DRay& r, double a, double b, double g) { return cylinderOracle(c, r, a, b, g); },
            c.base + c.axis * (0.5f * c.height), 1.05f * scale, true, 1.05f * scale, false,
            [c](const Ray& r, const ShapeHit& h) { return objectHitPoint(SceneView{}, c, r, h); }};
}

RectangleShape makeRectangle(float scale, Vec3 offset) {
    const Vec3 n = normalize(Vec3(0.2f, -1.0f, 0.3f));
    const Vec3 u = normalize(cross(Vec3(0, 1, 0), n) * -1.0f);
    const Vec3 v = cross(n, u);
    return {offset + Vec3(0.1f, 0.4f, -0.2f) * scale, u * (0.8f * scale), v * (0.5f * scale), n};
}

ShapeCase rectangleCase(float scale, Vec3 offset) {
    const RectangleShape rect = makeRectangle(scale, offset);
    return {[rect](const Ray& r, float a, float b, ShapeHit& h) { return intersectRectangle(rect, r, a, b, h); },
            [rect](const DRay& r, double a, double b, double g) { return rectangleOracle(rect, r, a, b, g); },
            rect.center, 0.95f * scale, false};
}

using CaseFactory = ShapeCase (*)(float, Vec3);
struct NamedFactory {
    const char* name;
    CaseFactory make;
};
const NamedFactory kShapes[] = {
    {"sphere", sphereCase}, {"box", boxCase}, {"cylinder", cylinderCase}, {"rectangle", rectangleCase}};

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

std::string describe(const Ray& r) {
    std::ostringstream s;
    s.precision(9);
    s << "o=(" << r.origin.x << ", " << r.origin.y << ", " << r.origin.z << ") d=(" << r.direction.x << ", "
      << r.direction.y << ", " << r.direction.z << ")";
    return s.str();
}

// ---- Comparing the float routine with the oracle. ----

// Rays within this fraction of the accuracy scale of the silhouette (or of the window ends) are
// ambiguous: float inputs rounded by far less than that could flip them.
constexpr double kGrow = 1e-5;

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
void compareOne(const ShapeCase& sc, const Ray& ray, float tMin, float tMax, Tally& tally, ShapeHit* out = nullptr,
                bool coordinateSlack = false) {
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

void expectClean(const Tally& t, const std::string& label) {
    EXPECT_EQ(t.failures, 0) << label << ": " << t.failures << " of " << t.rays << "; first: " << t.firstFailure;
    EXPECT_LE(t.ambiguous, t.rays / 100) << label << ": too many rays at the silhouette to mean anything";
}

// ---- Exact answers: helpers. ----

ShapeHit expectHit(bool got, const ShapeHit& h) {
    EXPECT_TRUE(got);
    return got ? h : ShapeHit{NAN, {NAN, NAN, NAN}, 0, 0.0f, 0.0f};
}
// t to a few ulps of the scale of the configuration.
void expectT(float t, double want, double scale, double ulps = 4) { EXPECT_NEAR(t, want, ulps * kEps * scale); }
void expectNormal(Vec3 n, Vec3 want, double tolerance = 4 * kEps) {
    EXPECT_NEAR(n.x, want.x, tolerance);
    EXPECT_NEAR(n.y, want.y, tolerance);
    EXPECT_NEAR(n.z, want.z, tolerance);
}

// ---- Sphere ----

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

// ---- Box ----

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
    // Random rays from outside and inside.
    Tally tally;
    Sampler sampler(11);
    const ShapeCase sc = boxCase(1.0f, {0, 0, 0});
    for (int i = 0; i < 5000; ++i) compareOne(sc, sampler.rayNear(sc), 0, kInf, tally);
    expectClean(tally, "box");
    EXPECT_GT(tally.hits, 1000);
}

// ---- Cylinder ----

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

TEST(IntersectCylinder, RandomRaysMatchTheOracle) {
    Tally tally;
    Sampler sampler(13);
    const ShapeCase sc = cylinderCase(1.0f, {0, 0, 0});
    for (int i = 0; i < 5000; ++i) compareOne(sc, sampler.rayNear(sc), 0, kInf, tally);
    expectClean(tally, "cylinder");
    EXPECT_GT(tally.hits, 1000);
}

// ---- Rectangle ----

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

TEST(IntersectRectangle, RandomRaysMatchTriangles) {
    Tally tally;
    Sampler sampler(17);
    const ShapeCase sc = rectangleCase(1.0f, {0, 0, 0});
    for (int i = 0; i < 5000; ++i) compareOne(sc, sampler.rayNear(sc), 0, kInf, tally);
    expectClean(tally, "rectangle");
    EXPECT_GT(tally.hits, 500);
}

TEST(IntersectSphere, RandomRaysMatchTheOracle) {
    Tally tally;
    Sampler sampler(19);
    const ShapeCase sc = sphereCase(1.0f, {0, 0, 0});
    for (int i = 0; i < 5000; ++i) {
        const Ray ray = sampler.rayNear(sc);
        compareOne(sc, ray, 0, kInf, tally);
        // And with a window cutting the near root.
        compareOne(sc, ray, float(sampler.uniform(0, 3)), float(sampler.uniform(3, 8)), tally);
    }
    expectClean(tally, "sphere");
    EXPECT_GT(tally.hits, 2000);
}

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
