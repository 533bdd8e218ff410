// Host only: the SIMD lanes that packet traversals share (occluded_packet.h for shadow rays, nearest_packet.h
// for camera rays): a packet of up to 64 rays from one origin, lane types as wide as the translation unit's ISA
// (4 SSE2, 8 AVX2, 16 AVX-512; renderer/backends/cpu/tile_render.h), the number type LaneOps over them, and
// spheres, boxes and cylinders tested against several rays at once: their own tests (objects/<kind>.h),
// instantiated for LaneOps, so a ray's roots, and the nearest of them in (0, tMax), are the scalar test's.
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
#if defined(__AVX512F__)
    return (LaneI)_mm512_maskz_mov_epi32((__mmask16)rays, _mm512_set1_epi32(-1));
#else
    LaneI bit;
    for (int i = 0; i < kLanes; ++i) bit[i] = int32_t(1u << i);
    return ((LaneI{} + int32_t(rays)) & bit) == bit;
#endif
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
    LaneF operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
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

inline V3 crossAccurate(Vec3 u, const V3& v) { return crossAccurateOf<LaneOps>(u, v); }
inline V3 crossAccurate(const V3& u, const V3& v) { return crossAccurateOf<LaneOps>(u, v); }

// The rays of group g.
struct Group {
    V3 d;
    LaneF tMax;
};
inline Group loadGroup(const RayPacket& p, int g) {
    const int o = g * kLanes;
    return {{load(p.dx + o), load(p.dy + o), load(p.dz + o)}, load(p.tMax + o)};
}

// The shapes' tests in lanes are inlined (TRAZO_HD_HOT) into the traversals' loops, where GCC would otherwise call
// some out of line.

// intersectSphere(s, Ray{origin, d}, 0, tMax, hit) lane by lane for the rays of `live`, hit.t in tHit and, when
// asked for, hit.normal in normal. Setup: sphereSetupOf<ScalarOps> (one origin) or <LaneOps> (the group's own).
template <class Setup>
TRAZO_HD_HOT uint64_t sphereHits(const SphereShape& s, const Setup& k, const Group& ray, uint64_t live, LaneF& tHit,
                                 V3* normal = nullptr) {
    LaneI lanes = laneMask(live) & !sphereBeyondReach(k.f, ray.d, k.reach2);
    if (!LaneOps::any(lanes)) return 0;
    SphereRootsOf<LaneOps> roots;
    if (!sphereRootsOf<LaneOps>(k, s.radius, ray.d, lanes, roots)) return 0;
    // intersectSphere's choice in selects: the near root where it lies in (0, tMax), else the far one.
    const LaneI nearIn = (roots.tNear > 0.0f) & (roots.tNear < ray.tMax);
    const LaneI farIn = (roots.tFar > 0.0f) & (roots.tFar < ray.tMax);
    tHit = nearIn ? roots.tNear : roots.tFar;
    if (normal) {
        const V3 along = ray.d * roots.halfChord;
        *normal = normalize(LaneOps::select(nearIn, roots.l - along, roots.l + along));
    }
    return bits(lanes & (nearIn | farIn));
}

// intersectBox(box, Ray{origin, d}, 0, tMax, hit) lane by lane: the lanes that hit, in tHit their hit.t and in
// face their hit.triangle (the face, boxSlabsOf). Origin: a Vec3 (one origin) or V3 (the group's own).
template <class Origin>
TRAZO_HD_HOT uint64_t boxHits(const BoxShape& box, const Origin& origin, const Group& ray, uint64_t live, LaneF& tHit,
                              LaneI& face) {
    LaneI lanes = laneMask(live), enterFace, exitFace;
    LaneF tEnter, tExit;
    if (!boxSlabsOf<LaneOps>(box, origin, ray.d, lanes, tEnter, tExit, enterFace, exitFace)) return 0;
    // intersectBox's choice in selects: where the line enters in (0, tMax), else where it leaves.
    const LaneI enterIn = (tEnter > 0.0f) & (tEnter < ray.tMax), exitIn = (tExit > 0.0f) & (tExit < ray.tMax);
    tHit = enterIn ? tEnter : tExit;
    face = enterIn ? enterFace : exitFace;
    return bits(lanes & (tEnter <= tExit) & (enterIn | exitIn));
}

// intersectCylinder(c, Ray{origin, d}, 0, tMax, hit) lane by lane: the lanes that hit, and in tHit their hit.t.
template <class Origin>
TRAZO_HD_HOT uint64_t cylinderHits(const CylinderShape& cyl, const Origin& origin, const Group& ray, uint64_t live,
                                   LaneF& tHit) {
    tHit = ray.tMax;
    return bits(cylinderHitsOf<LaneOps>(cyl, origin, ray.d, 0.0f, laneMask(live), tHit, nullptr));
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
                const LaneF lo = LaneOps::splat(node.bounds[axis][0][c] - origin[axis]);
                const LaneF hi = LaneOps::splat(node.bounds[axis][1][c] - origin[axis]);
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
// sphereSetups(s).group(g): the sphere's set-up for group g's rays, made once here for all groups.
struct SharedOrigin {
    Vec3 origin;
    Vec3 group(int) const { return origin; }
    Vec3 at(int) const { return origin; }
    struct SphereSetups {
        SphereSetupOf<ScalarOps> k;
        const SphereSetupOf<ScalarOps>& group(int) const { return k; }
    };
    SphereSetups sphereSetups(const SphereShape& s) const { return {sphereSetupOf<ScalarOps>(s, origin)}; }
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
    struct SphereSetups {
        const OwnOrigins& origins;
        const SphereShape& s;
        TRAZO_HD_HOT SphereSetupOf<LaneOps> group(int g) const { return sphereSetupOf<LaneOps>(s, origins.group(g)); }
    };
    SphereSetups sphereSetups(const SphereShape& s) const { return {*this, s}; }
};

// Object o against the rays of `live`, group by group, where its kind has a test in lanes (a sphere, box or
// cylinder; false for the others): each(g, hits, tHit, face, normal) with the rays of group g that hit (bit k:
// lane k), their t, the box faces hit where o is a box, the normals where it is a sphere and kNormals (else null).
// Origins: SharedOrigin or OwnOrigins.
template <bool kNormals, class Origins, class Each>
inline bool groupHits(const SceneView& scene, const ObjectRef& o, const Origins& origins, const RayPacket& rays,
                      uint64_t live, Each&& each) {
    const auto groups = [&](auto&& test) {
        for (int g = 0; g < kGroups; ++g) {
            const uint64_t lanes = (live >> (g * kLanes)) & kGroupBits;
            if (lanes) test(g, lanes, loadGroup(rays, g));
        }
    };
    LaneF tHit;
    switch (o.kind) {
        case ObjectKind::Sphere: {
            const SphereShape& s = scene.spheres[o.index];
            const auto setups = origins.sphereSetups(s);
            V3 normals;
            V3* const normal = kNormals ? &normals : nullptr;
            groups([&](int g, uint64_t lanes, const Group& ray) {
                const uint64_t hits = sphereHits(s, setups.group(g), ray, lanes, tHit, normal);
                each(g, hits, tHit, nullptr, normal);
            });
            return true;
        }
        case ObjectKind::Box: {
            const BoxShape& box = scene.boxes[o.index];
            LaneI face;
            groups([&](int g, uint64_t lanes, const Group& ray) {
                const uint64_t hits = boxHits(box, origins.group(g), ray, lanes, tHit, face);
                each(g, hits, tHit, &face, nullptr);
            });
            return true;
        }
        case ObjectKind::Cylinder: {
            const CylinderShape& cyl = scene.cylinders[o.index];
            groups([&](int g, uint64_t lanes, const Group& ray) {
                const uint64_t hits = cylinderHits(cyl, origins.group(g), ray, lanes, tHit);
                each(g, hits, tHit, nullptr, nullptr);
            });
            return true;
        }
        default:
            return false;
    }
}

// A node of a packet traversal and the rays still to visit it.
struct PacketEntry {
    uint32_t ref;
    uint64_t rays;
};

}  // namespace packet_detail

}  // namespace trazo
