// Host only: the SIMD lanes that packet traversals share (occluded_packet.h for shadow rays, nearest_packet.h
// for camera rays): a packet of up to 64 rays from one origin, lane types as wide as the translation unit's ISA
// (4 SSE2, 8 AVX2, 16 AVX-512; renderer/backends/cpu/tile_render.h), and spheres, boxes and cylinders tested
// against several rays at once. Each lane repeats its shape's scalar test operation for operation, so a ray's
// roots, and the nearest of them in (0, tMax), are the scalar test's bit for bit.
#pragma once

#if TRAZO_DEVICE_PATHS || defined(__CUDACC__)
#error "packet_lanes.h is host code: the device traces its rays one by one"
#endif

#include <immintrin.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/rng.h"
#include "integrator/scene_intersect.h"

namespace trazo {

constexpr int kPacketRays = 64;  // one bit per ray in a uint64_t

// One T per ray of a packet, none constructed: each element begins where it is written (placement new, or an
// assignment for the aggregates). Constructing 64 of each per shading point zeroed their vectors, a loop that
// showed in the profile of scene9_indirect_point.
template <class T>
union PerRay {
    T items[kPacketRays];
    PerRay() {}
    T& operator[](int i) { return items[i]; }
    T* data() { return items; }
};

// Rays from one origin: directions and the ends of their segments (0, tMax), structure of arrays.
struct RayPacket {
    alignas(64) float dx[kPacketRays];
    alignas(64) float dy[kPacketRays];
    alignas(64) float dz[kPacketRays];
    alignas(64) float tMax[kPacketRays];
};

namespace packet_detail {

#if defined(__AVX512F__)
constexpr int kLanes = 16;
#elif defined(__AVX2__) && defined(__FMA__)
constexpr int kLanes = 8;
#else
constexpr int kLanes = 4;
#endif
typedef float LaneF __attribute__((vector_size(kLanes * 4)));
typedef int32_t LaneI __attribute__((vector_size(kLanes * 4)));
typedef uint32_t LaneU __attribute__((vector_size(kLanes * 4)));
constexpr int kGroups = kPacketRays / kLanes;
constexpr uint64_t kGroupBits = kLanes == 64 ? ~0ull : (1ull << kLanes) - 1;

// The lanes of the groups up to the last ray of `rays` (bit i: ray i): a multiple of kLanes, 0 for none.
inline int groupedLanes(uint64_t rays) {
    return rays ? (64 - __builtin_clzll(rays) + kLanes - 1) / kLanes * kLanes : 0;
}
inline LaneF splat(float x) {
    LaneF v;
    for (int i = 0; i < kLanes; ++i) v[i] = x;
    return v;
}
inline LaneF load(const float* p) {
    LaneF v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
// Bit i set when lane i of the comparison result is true.
inline uint64_t bits(LaneI m) {
#if defined(__AVX512F__)
    return (uint64_t)_mm512_cmpneq_epi32_mask((__m512i)m, _mm512_setzero_si512());
#elif defined(__AVX2__) && defined(__FMA__)
    return (uint64_t)(unsigned)_mm256_movemask_ps((__m256)m);
#else
    return (uint64_t)(unsigned)_mm_movemask_ps((__m128)m);
#endif
}
// Lane i true (−1) where bit i of `rays` is set: bits' inverse.
inline LaneI laneMask(uint64_t rays) {
    LaneI bit;
    for (int i = 0; i < kLanes; ++i) bit[i] = int32_t(1u << i);
    return ((LaneI{} + int32_t(rays & kGroupBits)) & bit) != 0;
}
inline LaneF sqrt(LaneF x) {
#if defined(__AVX512F__)
    return (LaneF)_mm512_maskz_sqrt_ps((__mmask16)0xffff, (__m512)x);  // _mm512_sqrt_ps: a false -Wmaybe-uninitialized in GCC 12
#elif defined(__AVX2__) && defined(__FMA__)
    return (LaneF)_mm256_sqrt_ps((__m256)x);
#else
    return (LaneF)_mm_sqrt_ps((__m128)x);
#endif
}
// a·b + c rounded once, as fmaf: one instruction with FMA, else fmaf lane by lane (SSE2 has no fused
// multiply-add, and a product in double then a sum would round twice).
inline LaneF fma(LaneF a, LaneF b, LaneF c) {
#if defined(__AVX512F__)
    return (LaneF)_mm512_fmadd_ps((__m512)a, (__m512)b, (__m512)c);
#elif defined(__AVX2__) && defined(__FMA__)
    return (LaneF)_mm256_fmadd_ps((__m256)a, (__m256)b, (__m256)c);
#else
    LaneF r;
    for (int i = 0; i < kLanes; ++i) r[i] = fmaf(a[i], b[i], c[i]);
    return r;
#endif
}
inline LaneF copysign(LaneF magnitude, LaneF sign) {
    const LaneI signBit = (LaneI)splat(-0.0f);
    return (LaneF)(((LaneI)magnitude & ~signBit) | ((LaneI)sign & signBit));
}
inline LaneF fabs(LaneF x) { return (LaneF)((LaneI)x & ~(LaneI)splat(-0.0f)); }

// SampleStream{key, dimension}.next() lane by lane (core/rng.h: hashCombineBits, bitsToUnitFloat).
inline LaneF unitFloats(uint32_t key, LaneU dimension) {
    const LaneU x = hashCombineBits(key, dimension);
    return __builtin_convertvector((LaneI)(x >> 8), LaneF) * (1.0f / 16777216.0f);
}

// The lanes of one ray group, and of a Vec3 per lane. Its functions are core/vec3.h's, lane by lane; a Vec3
// operand is one vector for all lanes.
struct V3 {
    LaneF x, y, z;
    const LaneF& operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
};
inline V3 operator+(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator+(const V3& a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator+(Vec3 a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator-(const V3& a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator-(Vec3 a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(const V3& a, LaneF s) { return {a.x * s, a.y * s, a.z * s}; }
inline LaneF dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline LaneF dot(Vec3 a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline LaneF dot(const V3& a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 cross(const V3& a, const V3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline V3 cross(Vec3 a, const V3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline V3 cross(const V3& a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline LaneF length(const V3& a) { return sqrt(dot(a, a)); }
inline V3 normalize(const V3& a) { return a * (1.0f / sqrt(dot(a, a))); }
inline V3 abs(const V3& a) { return {fabs(a.x), fabs(a.y), fabs(a.z)}; }
inline LaneF maxOf(LaneF a, LaneF b) { return a > b ? a : b; }
inline LaneF maxComponent(const V3& a) { return maxOf(a.x, maxOf(a.y, a.z)); }
inline V3 applyToVector(const Affine3& m, const V3& v) { return {dot(m.row[0], v), dot(m.row[1], v), dot(m.row[2], v)}; }
inline V3 applyToPoint(const Affine3& m, const V3& p) { return applyToVector(m, p) + m.translation; }

// The number type of lanes (core/number_ops.h): sinCosOf, the shading formulas and the shape tests instantiated
// for it compute what their scalar code does lane by lane, bit for bit. Operands may mix lanes and one float.
struct LaneOps {
    using F = LaneF;
    using I = LaneI;
    using B = LaneI;  // −1 where true
    using V = V3;
    static LaneF splat(float x) { return packet_detail::splat(x); }
    static LaneF splat(LaneF x) { return x; }
    static V3 splat(Vec3 v) { return {splat(v.x), splat(v.y), splat(v.z)}; }
    static const V3& splat(const V3& v) { return v; }
    static bool any(LaneI m) { return bits(m) != 0; }
    static bool any(bool b) { return b; }
    static bool all(LaneI m) { return bits(m) == kGroupBits; }
    static bool all(bool b) { return b; }
    // minOf and maxOf of core/vec3.h.
    template <class X, class Y>
    static auto min(X a, Y b) { return a < b ? a : b; }
    template <class X, class Y>
    static auto max(X a, Y b) { return a > b ? a : b; }
    static LaneF sqrt(LaneF x) { return packet_detail::sqrt(x); }
    static float abs(float x) { return fabsf(x); }
    static LaneF abs(LaneF x) { return fabs(x); }
    static LaneF copysign(LaneF magnitude, LaneF sign) { return packet_detail::copysign(magnitude, sign); }
    static LaneF fma(LaneF a, LaneF b, LaneF c) { return packet_detail::fma(a, b, c); }
    // libm's expf in the lanes of `needed`, 0 in the others.
    static LaneF exp(LaneF x, LaneI needed) {
        LaneF e = {};
        for (uint64_t left = bits(needed); left; left &= left - 1) {
            const int i = __builtin_ctzll(left);
            e[i] = expf(x[i]);
        }
        return e;
    }
    static V3 select(LaneI m, const V3& a, const V3& b) { return {m ? a.x : b.x, m ? a.y : b.y, m ? a.z : b.z}; }
    static I truncate(F x) { return __builtin_convertvector(x, LaneI); }
    static F toFloat(I k) { return __builtin_convertvector(k, LaneF); }
};

// differenceOfProducts(a, b, c, d) of exact_float.h.
inline LaneF differenceOfProducts(LaneF a, LaneF b, LaneF c, LaneF d) {
    const LaneF cd = c * d;
    const LaneF error = fma(-c, d, cd);
    return fma(a, b, -cd) + error;
}
inline V3 crossAccurate(Vec3 u, const V3& v) {
    return {differenceOfProducts(splat(u.y), v.z, splat(u.z), v.y),
            differenceOfProducts(splat(u.z), v.x, splat(u.x), v.z),
            differenceOfProducts(splat(u.x), v.y, splat(u.y), v.x)};
}
inline V3 crossAccurate(const V3& u, const V3& v) {
    return {differenceOfProducts(u.y, v.z, u.z, v.y), differenceOfProducts(u.z, v.x, u.x, v.z),
            differenceOfProducts(u.x, v.y, u.y, v.x)};
}

// For rays with origins of their own (RayOrigins): the scalar helpers that the shape tests apply to the origin,
// lane by lane and operation for operation (core/vec3.h, core/affine.h, geometry/exact_float.h). Overloads for
// a float or a Vec3 let one test serve both a shared origin and one per ray.
inline float absOf(float x) { return fabsf(x); }
inline LaneF absOf(LaneF x) { return fabs(x); }
inline LaneF asLanes(float x) { return splat(x); }
inline LaneF asLanes(LaneF x) { return x; }
inline float component(Vec3 v, int axis) { return v[axis]; }
inline LaneF component(const V3& v, int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }
inline Vec3 applyToPoint(const Affine3& m, Vec3 p) { return m.applyToPoint(p); }
struct TwoLanes {
    LaneF hi, lo;
};
inline TwoLanes twoSum(LaneF a, LaneF b) {
    const LaneF sum = a + b;
    const LaneF bVirtual = sum - a;
    const LaneF aVirtual = sum - bVirtual;
    return {sum, (a - aVirtual) + (b - bVirtual)};
}
inline TwoLanes twoProduct(LaneF a, LaneF b) {
    const LaneF p = a * b;
    return {p, fma(a, b, -p)};
}
inline LaneF lengthSquaredMinusSquareAccurate(const V3& u, float r) {
    const TwoLanes x = twoProduct(u.x, u.x);
    const TwoLanes y = twoProduct(u.y, u.y);
    const TwoLanes z = twoProduct(u.z, u.z);
    const TwoFloat rr = trazo::twoProduct(r, r);
    const TwoLanes s1 = twoSum(x.hi, y.hi);
    const TwoLanes s2 = twoSum(s1.hi, z.hi);
    const TwoLanes s3 = twoSum(s2.hi, splat(-rr.hi));
    return s3.hi + ((s1.lo + s2.lo + s3.lo) + (x.lo + y.lo + z.lo - rr.lo));
}

// The rays of group g.
struct Group {
    V3 d;
    LaneF tMax;
};
inline Group loadGroup(const RayPacket& p, int g) {
    const int o = g * kLanes;
    return {{load(p.dx + o), load(p.dy + o), load(p.dz + o)}, load(p.tMax + o)};
}

// intersectSphere(s, Ray{origin, d}, 0, tMax, hit) lane by lane, hit.t only: sphereRoots with what depends on
// the origin only computed once.
struct SphereSetup {
    Vec3 f, fLo;
    float reach2, r, c;
};
inline SphereSetup sphereSetup(const SphereShape& s, Vec3 origin) {
    SphereSetup k;
    const Vec3 f0 = origin - s.center;
    const float margin = 1e-5f * (maxComponent(abs(origin)) + maxComponent(abs(s.center)) + maxComponent(abs(f0)));
    const float reach = s.radius + margin;
    k.reach2 = reach * reach;
    const TwoFloat fx = trazo::twoSum(origin.x, -s.center.x);
    const TwoFloat fy = trazo::twoSum(origin.y, -s.center.y);
    const TwoFloat fz = trazo::twoSum(origin.z, -s.center.z);
    k.f = Vec3(fx.hi, fy.hi, fz.hi);
    k.fLo = Vec3(fx.lo, fy.lo, fz.lo);
    k.r = s.radius;
    k.c = lengthSquaredMinusSquareAccurate(k.f, k.r) + 2.0f * dot(k.f, k.fLo);
    // sphereRoots' reject uses f = origin − centre in plain float: twoSum's hi is that very sum.
    return k;
}

// sphereSetup's values for rays of a group with origins of their own, lane by lane.
struct SphereSetupLanes {
    V3 f, fLo;
    LaneF reach2;
    float r;
    LaneF c;
};
inline SphereSetupLanes sphereSetup(const SphereShape& s, const V3& origin) {
    SphereSetupLanes k;
    const V3 f0 = origin - s.center;
    const LaneF margin = 1e-5f * (maxComponent(abs(origin)) + maxComponent(abs(s.center)) + maxComponent(abs(f0)));
    const LaneF reach = s.radius + margin;
    k.reach2 = reach * reach;
    const TwoLanes fx = twoSum(origin.x, splat(-s.center.x));
    const TwoLanes fy = twoSum(origin.y, splat(-s.center.y));
    const TwoLanes fz = twoSum(origin.z, splat(-s.center.z));
    k.f = {fx.hi, fy.hi, fz.hi};
    k.fLo = {fx.lo, fy.lo, fz.lo};
    k.r = s.radius;
    k.c = lengthSquaredMinusSquareAccurate(k.f, k.r) + 2.0f * dot(k.f, k.fLo);
    return k;
}
// Returns the lanes of `live` that hit; tHit holds their t (the nearer root in (0, tMax), else the farther) and,
// when asked for, normal their hit.normal. Setup: SphereSetup (one origin) or SphereSetupLanes.
template <class Setup>
inline uint64_t sphereHits(const Setup& k, const Group& ray, uint64_t live, LaneF& tHit, V3* normal = nullptr) {
    const V3& d = ray.d;
    const LaneF dd = dot(d, d);
    const V3 fd = cross(k.f, d);
    live &= bits(!(dot(fd, fd) > k.reach2 * dd));
    if (!live) return 0;
    const LaneF a = dd;
    const LaneF b = dot(k.f, d) + dot(k.fLo, d);
    const auto c = k.c;
    const V3 ca = crossAccurate(k.f, d);
    const V3 cl = cross(k.fLo, d);
    const V3 x = {ca.x + cl.x, ca.y + cl.y, ca.z + cl.z};
    const V3 lc = cross(d, x);
    const LaneF invA = 1.0f / a;
    const V3 l = {lc.x * invA, lc.y * invA, lc.z * invA};
    const LaneF lLength = sqrt(dot(l, l));
    const float r = k.r;
    const LaneI nearForm = b * b + a * absOf(c) < a * lLength * (r + lLength);
    const LaneF discriminant = nearForm ? fma(b, b, -a * c) : a * ((r - lLength) * (r + lLength));
    live &= bits(discriminant >= 0.0f);
    if (!live) return 0;
    const LaneF root = sqrt(discriminant);
    const LaneF q = -b - copysign(root, b);
    const LaneF t0 = q / a;
    const LaneF t1 = q != 0.0f ? c / q : t0;
    const LaneI swap = t0 > t1;
    const LaneF tNear = swap ? t1 : t0, tFar = swap ? t0 : t1;
    const LaneF tMax = ray.tMax;
    const LaneI nearIn = (tNear > 0.0f) & (tNear < tMax), farIn = (tFar > 0.0f) & (tFar < tMax);
    tHit = nearIn ? tNear : tFar;
    if (normal) {  // intersectSphere's normalize(l ∓ d·halfChord)
        const LaneF halfChord = root / a;
        const V3 along = {d.x * halfChord, d.y * halfChord, d.z * halfChord};
        const V3 v = {nearIn ? l.x - along.x : l.x + along.x, nearIn ? l.y - along.y : l.y + along.y,
                      nearIn ? l.z - along.z : l.z + along.z};
        const LaneF inv = 1.0f / sqrt(dot(v, v));
        *normal = {v.x * inv, v.y * inv, v.z * inv};
    }
    return live & bits(nearIn | farIn);
}

// intersectBox(box, Ray{origin, d}, 0, tMax, hit) lane by lane: the lanes that hit, in tHit their hit.t and in
// face the face hit, 2·axis + 1 for the + face of the axis, 2·axis for the − face (hit.normal is
// boxFaceNormal(box, axis, ±1)).
// Origin: a Vec3 (one origin) or V3 (the group's own).
template <class Origin>
inline uint64_t boxHits(const BoxShape& box, const Origin& oWorld, const Group& ray, uint64_t live, LaneF& tHit,
                        LaneI& face) {
    const Origin o = applyToPoint(box.objectFromWorld, oWorld);
    const V3 d = {dot(box.objectFromWorld.row[0], ray.d), dot(box.objectFromWorld.row[1], ray.d),
                  dot(box.objectFromWorld.row[2], ray.d)};
    LaneF tEnter = splat(-INFINITY), tExit = splat(INFINITY);
    LaneI enterFace = {}, exitFace = {};
    for (int axis = 0; axis < 3; ++axis) {
        const auto oi = component(o, axis);
        const LaneF di = axis == 0 ? d.x : (axis == 1 ? d.y : d.z);
        const LaneI parallel = di == 0.0f;
        live &= ~bits(parallel & ((asLanes(oi) < -0.5f) | (asLanes(oi) > 0.5f)));  // parallel outside the slab
        const LaneF tLow = (-0.5f - oi) / di;
        const LaneF tHigh = (0.5f - oi) / di;
        const LaneI forward = di > 0.0f;
        const LaneF tNear = forward ? tLow : tHigh;
        const LaneF tFar = forward ? tHigh : tLow;
        const LaneI enters = ~parallel & (tNear > tEnter), exits = ~parallel & (tFar < tExit);
        tEnter = enters ? tNear : tEnter;
        tExit = exits ? tFar : tExit;
        // forward is −1 where true: forward rays enter through the − face and leave through the + face.
        enterFace = enters ? 2 * axis + 1 + forward : enterFace;
        exitFace = exits ? 2 * axis - forward : exitFace;
    }
    const LaneF tMax = ray.tMax;
    const LaneI enterIn = (tEnter > 0.0f) & (tEnter < tMax), exitIn = (tExit > 0.0f) & (tExit < tMax);
    tHit = enterIn ? tEnter : tExit;
    face = enterIn ? enterFace : exitFace;
    return live & bits((tEnter <= tExit) & (enterIn | exitIn));
}
template <class Origin>
inline uint64_t boxHits(const BoxShape& box, const Origin& oWorld, const Group& ray, uint64_t live, LaneF& tHit) {
    LaneI face;
    return boxHits(box, oWorld, ray, live, tHit, face);
}

// intersectCylinder(c, Ray{origin, d}, 0, tMax, hit) lane by lane: the lanes that hit, and in tHit their hit.t.
template <class Origin>
inline uint64_t cylinderHits(const CylinderShape& cyl, const Origin& origin, const Group& ray, uint64_t live,
                             LaneF& tHit) {
    const Vec3 axis = cyl.axis;
    const float r = cyl.radius;
    const Origin f = origin - cyl.base;
    const V3& d = ray.d;
    const Origin fPerp = crossAccurate(axis, f);
    const V3 dPerp = crossAccurate(axis, d);
    const auto fAlong = dot(axis, f);
    const LaneF dAlong = dot(axis, d);

    LaneF tBest = ray.tMax;
    LaneI found = splat(0.0f) != 0.0f;  // all false
    const LaneF a = dot(dPerp, dPerp);
    const LaneI sideLanes = a > 0.0f;
    if (bits(sideLanes) & live) {
        const LaneF b = dot(fPerp, dPerp);
        const LaneF ba = b / a;
        const V3 l = {fPerp.x - dPerp.x * ba, fPerp.y - dPerp.y * ba, fPerp.z - dPerp.z * ba};
        const LaneF lLength = sqrt(dot(l, l));
        const LaneF discriminant = a * ((r - lLength) * (r + lLength));
        const LaneI roots = sideLanes & (discriminant >= 0.0f);
        if (bits(roots) & live) {
            const LaneF q = -b - copysign(sqrt(discriminant), b);
            const auto c = dot(fPerp, fPerp) - r * r;
            LaneF t0 = q / a;
            LaneF t1 = q != 0.0f ? c / q : t0;
            const LaneI swap = t0 > t1;
            const LaneF first = swap ? t1 : t0, second = swap ? t0 : t1;
            // The nearer root between the caps wins; the farther counts only when the nearer does not.
            LaneI taken = found;  // all false
            for (int i = 0; i < 2; ++i) {
                const LaneF t = i == 0 ? first : second;
                const LaneF height = fAlong + t * dAlong;
                const LaneI hit = roots & ~taken & (t > 0.0f) & (t < tBest) & (height >= 0.0f) & (height <= cyl.height);
                tBest = hit ? t : tBest;
                found |= hit;
                taken |= hit;
            }
        }
    }
    const LaneI caps = dAlong != 0.0f;
    if (bits(caps) & live) {
        for (int i = 0; i < 2; ++i) {
            const float capHeight = i == 0 ? 0.0f : cyl.height;
            const LaneF t = (capHeight - fAlong) / dAlong;
            const V3 radial = {fPerp.x + dPerp.x * t, fPerp.y + dPerp.y * t, fPerp.z + dPerp.z * t};
            const LaneI hit = caps & (t > 0.0f) & (t < tBest) & (dot(radial, radial) <= r * r);
            tBest = hit ? t : tBest;
            found |= hit;
        }
    }
    tHit = tBest;
    return live & bits(found);
}

// makeBoxRay's inverse directions of a packet's rays, per axis.
struct InverseDirections {
    alignas(64) float axis[3][kPacketRays];
};
inline InverseDirections inverseDirections(const RayPacket& rays) {
    InverseDirections inv;
    for (int i = 0; i < kPacketRays; i += kLanes) {
        const LaneF x = 1.0f / load(rays.dx + i), y = 1.0f / load(rays.dy + i), z = 1.0f / load(rays.dz + i);
        std::memcpy(inv.axis[0] + i, &x, sizeof x);
        std::memcpy(inv.axis[1] + i, &y, sizeof y);
        std::memcpy(inv.axis[2] + i, &z, sizeof z);
    }
    return inv;
}

// out[c]: the rays of `live` that enter child c of the node over (0, tMax[ray]): intersectChildren per ray,
// (bound − origin)·invDirection with the near plane's bound by the sign of invDirection (the max plane first
// when it is < 0), the same selects, the same exit widening.
template <class Origins>
inline void raysEnteringChildren(const WideBvhNode& node, const Origins& origins, const InverseDirections& inv,
                                 const float* tMaxOfRays, uint64_t live, uint64_t out[kBvhWidth]) {
    for (int c = 0; c < kBvhWidth; ++c) out[c] = 0;
    for (int g = 0; g < kGroups; ++g) {
        const uint64_t lanes = (live >> (g * kLanes)) & kGroupBits;
        if (!lanes) continue;
        const int o = g * kLanes;
        const LaneF invAxis[3] = {load(inv.axis[0] + o), load(inv.axis[1] + o), load(inv.axis[2] + o)};
        const LaneI maxFirst[3] = {invAxis[0] < 0.0f, invAxis[1] < 0.0f, invAxis[2] < 0.0f};
        const LaneF tMax = load(tMaxOfRays + o);
        const auto origin = origins.group(g);
        for (int c = 0; c < kBvhWidth; ++c) {
            if (node.child[c] == kBvhEmptyLane) continue;
            LaneF t0 = splat(0.0f), t1 = tMax;
            for (int axis = 0; axis < 3; ++axis) {
                const LaneF lo = asLanes(node.bounds[axis][0][c] - component(origin, axis));
                const LaneF hi = asLanes(node.bounds[axis][1][c] - component(origin, axis));
                const LaneF tNear = (maxFirst[axis] ? hi : lo) * invAxis[axis];
                const LaneF tFar = (maxFirst[axis] ? lo : hi) * invAxis[axis];
                t0 = tNear > t0 ? tNear : t0;
                t1 = tFar < t1 ? tFar : t1;
            }
            out[c] |= (bits(t0 <= t1 * kBoxExitScale) & lanes) << o;
        }
    }
}

// Where a packet's rays start: one origin for all (SharedOrigin), or one per ray (OwnOrigins over RayOrigins).
// group(g): the origin of group g's rays, a Vec3 or the lanes' V3; at(i): ray i's.
struct SharedOrigin {
    Vec3 origin;
    Vec3 group(int) const { return origin; }
    Vec3 at(int) const { return origin; }
};

}  // namespace packet_detail

// The origins of a packet's rays when each has its own, structure of arrays beside RayPacket.
struct RayOrigins {
    alignas(64) float ox[kPacketRays];
    alignas(64) float oy[kPacketRays];
    alignas(64) float oz[kPacketRays];
};

namespace packet_detail {

struct OwnOrigins {
    const RayOrigins& origins;
    V3 group(int g) const {
        const int o = g * kLanes;
        return {load(origins.ox + o), load(origins.oy + o), load(origins.oz + o)};
    }
    Vec3 at(int i) const { return Vec3(origins.ox[i], origins.oy[i], origins.oz[i]); }
};

// A node of a packet traversal and the rays still to visit it.
struct PacketEntry {
    uint32_t ref;
    uint64_t rays;
};

}  // namespace packet_detail

}  // namespace trazo
