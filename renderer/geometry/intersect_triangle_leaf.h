// A BVH leaf's triangles (at most four) against one ray (host and device): the nearest hit, and whether any
// hits. The device loops over intersectTriangle; the host tests the four at once with SSE (and, in the AVX2 and
// AVX-512 kernels, two blocks of four at once; in the AVX-512 kernels' closest-hit test, up to four), the same IEEE
// operations in the same order lane by lane, so both backends find the same triangle at the same t.
#pragma once

#include <cstdint>

#include "core/host_simd.h"
#include "geometry/intersect_triangle.h"

namespace trazo {

constexpr uint32_t kMaxLeafTriangles = 4;

// A mesh triangle in world space, as BVH leaves store them (shading data lives apart, objects/mesh.h).
struct MeshTriangle {
    Vec3 p0, p1, p2;
};

// Up to four consecutive triangles of a mesh transposed for lane tests: v[k][axis][lane] is vertex k of
// triangle first + lane (lanes past count repeat the first). Host only: where the CPU backend traverses meshes
// over eight-wide nodes, their leaves refer to these (flatten/flatten_mesh.h, widenMeshBvhs), so a leaf test
// loads its vertices as they are used instead of gathering and transposing four 36-byte triangles.
struct alignas(16) TriangleBlock {
    float v[3][3][4];
    uint32_t first;  // the first triangle, counted from the mesh's first
    uint32_t count;  // its triangles (1–4)
    uint32_t padding[2];
};
static_assert(sizeof(TriangleBlock) == 160, "144 bytes of vertices, the first triangle and the count");

// Vertex k (0, 1, 2 for p0, p1, p2) of the block's triangle in `lane`.
inline Vec3 blockVertex(const TriangleBlock& block, int k, uint32_t lane) {
    return Vec3(block.v[k][0][lane], block.v[k][1][lane], block.v[k][2][lane]);
}

// Nearest hit among triangles[0, count) within (tMin, tMax): what a loop over intersectTriangle that
// narrows tMax keeps, i.e. the smallest t, and of equal ones the first. `which` is its index.
TRAZO_HD bool intersectTrianglesLoop(const TriangleRay& r, const MeshTriangle* triangles, uint32_t count, float tMin,
                                     float tMax, TriangleHit& hit, uint32_t& which) {
    bool any = false;
    for (uint32_t i = 0; i < count; ++i) {
        if (intersectTriangle(r, triangles[i].p0, triangles[i].p1, triangles[i].p2, tMin, tMax, hit)) {
            tMax = hit.t;
            which = i;
            any = true;
        }
    }
    return any;
}

// Whether any of triangles[0, count) is hit within (tMin, tMax): the first hit ends the loop.
TRAZO_HD bool anyTriangleHit(const TriangleRay& r, const MeshTriangle* triangles, uint32_t count, float tMin,
                             float tMax) {
    TriangleHit hit;
    for (uint32_t i = 0; i < count; ++i)
        if (intersectTriangle(r, triangles[i].p0, triangles[i].p1, triangles[i].p2, tMin, tMax, hit)) return true;
    return false;
}

#if TRAZO_HOST_SSE
namespace triangle_detail {

// The lane operations intersectLanesAlong takes: four lanes (SSE2), or eight where host code is compiled for AVX2.
struct Lanes4 {
    using V = __m128;
    enum : int { kAll = 0xf };  // every lane's bit (an enumerator: -fno-weak mishandles inline variables)
    static V set1(float x) { return _mm_set1_ps(x); }
    static V zero() { return _mm_setzero_ps(); }
    static V add(V a, V b) { return _mm_add_ps(a, b); }
    static V sub(V a, V b) { return _mm_sub_ps(a, b); }
    static V mul(V a, V b) { return _mm_mul_ps(a, b); }
    static V div(V a, V b) { return _mm_div_ps(a, b); }
    static V bitAnd(V a, V b) { return _mm_and_ps(a, b); }
    static V bitOr(V a, V b) { return _mm_or_ps(a, b); }
    static V andNot(V a, V b) { return _mm_andnot_ps(a, b); }
    static V equal(V a, V b) { return _mm_cmpeq_ps(a, b); }
    static V less(V a, V b) { return _mm_cmplt_ps(a, b); }
    static V greater(V a, V b) { return _mm_cmpgt_ps(a, b); }
    static int mask(V a) { return _mm_movemask_ps(a); }
    static void store(float* out, V a) { _mm_store_ps(out, a); }
};

#if TRAZO_HOST_AVX
struct Lanes8 {
    using V = __m256;
    enum : int { kAll = 0xff };
    static V set1(float x) { return _mm256_set1_ps(x); }
    static V zero() { return _mm256_setzero_ps(); }
    static V add(V a, V b) { return _mm256_add_ps(a, b); }
    static V sub(V a, V b) { return _mm256_sub_ps(a, b); }
    static V mul(V a, V b) { return _mm256_mul_ps(a, b); }
    static V div(V a, V b) { return _mm256_div_ps(a, b); }
    static V bitAnd(V a, V b) { return _mm256_and_ps(a, b); }
    static V bitOr(V a, V b) { return _mm256_or_ps(a, b); }
    static V andNot(V a, V b) { return _mm256_andnot_ps(a, b); }
    static V equal(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_EQ_OQ); }
    static V less(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_LT_OQ); }
    static V greater(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_GT_OQ); }
    static int mask(V a) { return _mm256_movemask_ps(a); }
    static void store(float* out, V a) { _mm256_store_ps(out, a); }
};
#endif

#if TRAZO_HOST_AVX512
// Sixteen lanes; comparisons give mask registers, which the test combines as it combines Lanes4's vector masks.
struct Lanes16 {
    using V = __m512;
    using M = __mmask16;
    enum : int { kAll = 0xffff };
    static V set1(float x) { return _mm512_set1_ps(x); }
    static V zero() { return _mm512_setzero_ps(); }
    static V add(V a, V b) { return _mm512_add_ps(a, b); }
    static V sub(V a, V b) { return _mm512_sub_ps(a, b); }
    static V mul(V a, V b) { return _mm512_mul_ps(a, b); }
    static V div(V a, V b) { return _mm512_div_ps(a, b); }
    static M bitAnd(M a, M b) { return (M)(a & b); }
    static M bitOr(M a, M b) { return (M)(a | b); }
    static M andNot(M a, M b) { return (M)(~a & b); }
    static M equal(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_EQ_OQ); }
    static M less(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ); }
    static M greater(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_GT_OQ); }
    static int mask(M a) { return (int)a; }
    static void store(float* out, V a) { _mm512_store_ps(out, a); }
};
#endif

// Four triangles' vertices as structure of arrays: v[k][axis] holds vertex k's coordinate on that axis.
struct Triangles4 {
    __m128 v[3][3];
};

// Transposes up to four 36-byte triangles (lanes past `count` repeat triangle 0; the caller ignores them).
// Out of line: where GCC 12 inlines it into the any-hit mesh traversal, the traversal takes 4 % more instructions
// (callgrind, scene8_textured_mesh: meshBlocks 905 M → 943 M instructions with it inlined).
__attribute__((noinline)) inline Triangles4 loadTriangles4(const MeshTriangle* triangles, uint32_t count) {
    static_assert(sizeof(MeshTriangle) == 9 * sizeof(float), "MeshTriangle is read as nine packed floats");
    const float* t[4];
    for (uint32_t k = 0; k < 4; ++k) t[k] = reinterpret_cast<const float*>(triangles + (k < count ? k : 0));
    // Rows: floats 0–3 (p0.xyz, p1.x) and 4–7 (p1.yz, p2.xy) of each triangle; float 8 (p2.z) on its own.
    __m128 a0 = _mm_loadu_ps(t[0]), a1 = _mm_loadu_ps(t[1]), a2 = _mm_loadu_ps(t[2]), a3 = _mm_loadu_ps(t[3]);
    __m128 b0 = _mm_loadu_ps(t[0] + 4), b1 = _mm_loadu_ps(t[1] + 4), b2 = _mm_loadu_ps(t[2] + 4),
           b3 = _mm_loadu_ps(t[3] + 4);
    _MM_TRANSPOSE4_PS(a0, a1, a2, a3);
    _MM_TRANSPOSE4_PS(b0, b1, b2, b3);
    Triangles4 out;
    out.v[0][0] = a0, out.v[0][1] = a1, out.v[0][2] = a2;
    out.v[1][0] = a3, out.v[1][1] = b0, out.v[1][2] = b1;
    out.v[2][0] = b2, out.v[2][1] = b3, out.v[2][2] = _mm_setr_ps(t[0][8], t[1][8], t[2][8], t[3][8]);
    return out;
}

// A leaf as triangles in the mesh's array; transposed where it is tested (transposedLeaf).
struct TriangleSpan {
    const MeshTriangle* triangles;
    uint32_t count;
};

inline Triangles4 transposedLeaf(TriangleSpan leaf) { return loadTriangles4(leaf.triangles, leaf.count); }

// Vertex k's coordinates on one axis, four lanes.
inline __m128 vertexLanes(const Triangles4& tri, int k, int axis) { return tri.v[k][axis]; }

#if TRAZO_HOST_AVX
// Two blocks tested together, eight lanes: the first's four, then the second's (the same block twice for one).
struct BlockPair {
    const TriangleBlock& first;
    const TriangleBlock& second;
};
inline const BlockPair& transposedLeaf(const BlockPair& pair) { return pair; }

// A pair as the any-hit test reads it: an intersectLanes of its own, so the closest-hit test's keeps one caller
// (with two callers, GCC called a block test out of line from the closest-hit traversal: bvh_bench's bunny primary
// rays 4.5 % slower).
struct AnyHitPair {
    BlockPair pair;
};
inline const BlockPair& transposedLeaf(const AnyHitPair& leaf) { return leaf.pair; }

inline __m256 vertexLanes(const BlockPair& pair, int k, int axis) {
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_load_ps(pair.first.v[k][axis])),
                                _mm_load_ps(pair.second.v[k][axis]), 1);
}
#endif

#if TRAZO_HOST_AVX512
// Three or four consecutive blocks tested together, sixteen lanes (the third block twice for three).
struct BlockQuad {
    const TriangleBlock* blocks;
    bool four;
};
inline const BlockQuad& transposedLeaf(const BlockQuad& quad) { return quad; }

inline __m512 vertexLanes(const BlockQuad& quad, int k, int axis) {
    const __m512 first = _mm512_castps128_ps512(_mm_load_ps(quad.blocks[0].v[k][axis]));
    const __m512 two = _mm512_insertf32x4(first, _mm_load_ps(quad.blocks[1].v[k][axis]), 1);
    const __m512 three = _mm512_insertf32x4(two, _mm_load_ps(quad.blocks[2].v[k][axis]), 2);
    return _mm512_insertf32x4(three, _mm_load_ps(quad.blocks[quad.four ? 3 : 2].v[k][axis]), 3);
}
#endif

// intersectSheared for four, eight or sixteen triangles (a TriangleSpan; a BlockPair where host code is compiled
// for AVX2; a BlockQuad for AVX-512). Returns the mask of lanes hit within (tMin, tMax), with t and the reciprocal
// determinant per lane, or −1 when a lane has an edge function of exactly zero: the caller then falls back to the
// scalar test, which re-evaluates it in double. A span is transposed here rather than by the caller, so its
// vertices stay in registers (any-hit traversal: 3-4 % fewer rays a second the other way, bvh_bench).
template <class L, int KZ, class Leaf>
inline int intersectLanesAlong(const TriangleRay& r, const Leaf& leaf, float tMin, float tMax, typename L::V& t,
                               typename L::V& invDet, typename L::V& v, typename L::V& w) {
    using V = typename L::V;
    constexpr int KX = KZ == 2 ? 0 : KZ + 1, KY = KX == 2 ? 0 : KX + 1;
    const auto& tri = transposedLeaf(leaf);
    const V ox = L::set1(r.origin[KX]), oy = L::set1(r.origin[KY]), oz = L::set1(r.origin[KZ]);
    const V sx = L::set1(r.sx), sy = L::set1(r.sy), sz = L::set1(r.sz);
    V x[3], y[3], z[3];
    for (int k = 0; k < 3; ++k) {
        const V px = L::sub(vertexLanes(tri, k, KX), ox), py = L::sub(vertexLanes(tri, k, KY), oy);
        z[k] = L::sub(vertexLanes(tri, k, KZ), oz);
        x[k] = L::sub(px, L::mul(sx, z[k]));
        y[k] = L::sub(py, L::mul(sy, z[k]));
    }
    // triangleEdge(c, b), (a, c), (b, a): px·qy − py·qx.
    const V u = L::sub(L::mul(x[2], y[1]), L::mul(y[2], x[1]));
    v = L::sub(L::mul(x[0], y[2]), L::mul(y[0], x[2]));
    w = L::sub(L::mul(x[1], y[0]), L::mul(y[1], x[0]));
    const V zero = L::zero();
    // Masks: vectors of L::V, or Lanes16's mask registers.
    const auto anyZero = L::bitOr(L::equal(u, zero), L::bitOr(L::equal(v, zero), L::equal(w, zero)));
    if (L::mask(anyZero)) return -1;
    const auto anyNegative = L::bitOr(L::less(u, zero), L::bitOr(L::less(v, zero), L::less(w, zero)));
    const auto anyPositive = L::bitOr(L::greater(u, zero), L::bitOr(L::greater(v, zero), L::greater(w, zero)));
    const auto mixedSigns = L::bitAnd(anyNegative, anyPositive);
    if (L::mask(mixedSigns) == L::kAll) return 0;  // most leaves a ray reaches: no division needed
    const V det = L::add(L::add(u, v), w);
    const V tScaled =
        L::add(L::add(L::mul(u, L::mul(sz, z[0])), L::mul(v, L::mul(sz, z[1]))), L::mul(w, L::mul(sz, z[2])));
    invDet = L::div(L::set1(1.0f), det);
    t = L::mul(tScaled, invDet);
    // A lane with mixed signs or det = 0 misses; so does a NaN t (the comparisons fail).
    const auto inRange = L::bitAnd(L::greater(t, L::set1(tMin)), L::less(t, L::set1(tMax)));
    const auto hit = L::andNot(L::bitOr(mixedSigns, L::equal(det, zero)), inRange);
    return L::mask(hit);
}

template <class L, class Leaf>
inline int intersectLanes(const TriangleRay& r, const Leaf& leaf, float tMin, float tMax, typename L::V& t,
                          typename L::V& invDet, typename L::V& v, typename L::V& w) {
    if (r.kz == 2) return intersectLanesAlong<L, 2>(r, leaf, tMin, tMax, t, invDet, v, w);
    if (r.kz == 0) return intersectLanesAlong<L, 0>(r, leaf, tMin, tMax, t, invDet, v, w);
    return intersectLanesAlong<L, 1>(r, leaf, tMin, tMax, t, invDet, v, w);
}

// The nearest of the lanes in `mask` (the first of equal ones), as intersectTrianglesLoop would report it.
template <class L>
inline bool nearestLane(int mask, typename L::V t, typename L::V invDet, typename L::V v, typename L::V w,
                        TriangleHit& hit, uint32_t& which) {
    if (!mask) return false;
    constexpr int kWidth = sizeof(typename L::V) / sizeof(float);
    alignas(64) float ts[kWidth], invDets[kWidth], vs[kWidth], ws[kWidth];
    L::store(ts, t);
    int best = __builtin_ctz((unsigned)mask);
    for (unsigned m = (unsigned)mask & ((unsigned)mask - 1); m; m &= m - 1) {  // the lanes hit, not all of them
        const int k = __builtin_ctz(m);
        if (ts[k] < ts[best]) best = k;
    }
    L::store(invDets, invDet), L::store(vs, v), L::store(ws, w);
    hit.t = ts[best];
    hit.b1 = vs[best] * invDets[best];
    hit.b2 = ws[best] * invDets[best];
    which = (uint32_t)best;
    return true;
}

}  // namespace triangle_detail
#endif

// Nearest hit among the leaf's triangles[0, count), count ≤ kMaxLeafTriangles; see intersectTrianglesLoop.
TRAZO_HD bool intersectTriangleLeaf(const TriangleRay& r, const MeshTriangle* triangles, uint32_t count, float tMin,
                                    float tMax, TriangleHit& hit, uint32_t& which) {
#if TRAZO_HOST_SSE
    using namespace triangle_detail;
    __m128 t, invDet, v, w;
    int mask = intersectLanes<Lanes4>(r, TriangleSpan{triangles, count}, tMin, tMax, t, invDet, v, w);
    if (mask < 0) return intersectTrianglesLoop(r, triangles, count, tMin, tMax, hit, which);
    return nearestLane<Lanes4>(mask & ((1 << count) - 1), t, invDet, v, w, hit, which);
#else
    return intersectTrianglesLoop(r, triangles, count, tMin, tMax, hit, which);
#endif
}

#if TRAZO_HOST_AVX
// A leaf lane's blocks (1–4, consecutive, all full but the last) as the pairs they are tested in: blocks[0] and
// blocks[1], or blocks[0] alone where it is the last. Eight lanes cost a 256-bit unit what four do; against a block
// at a time (bvh_bench, one thread, interleaved): bunny random rays 1.05–1.07×, the million-triangle sphere's camera
// and shadow rays 1.03–1.05×, bunny camera rays 0.98–1.07×.
struct BlockRun {
    const TriangleBlock* blocks;
    bool pair;
    triangle_detail::BlockPair lanes() const { return {blocks[0], blocks[pair ? 1 : 0]}; }
    uint32_t count() const { return pair ? 4 + blocks[1].count : blocks[0].count; }
    int laneMask() const { return pair ? 0x0f | ((1 << blocks[1].count) - 1) << 4 : (1 << blocks[0].count) - 1; }
};

// intersectTriangleLeaf over the run's triangles (the mesh's from blocks[0].first), the same answer bit for bit:
// `which` counts from blocks[0].first.
inline bool intersectBlockRun(const TriangleRay& r, const BlockRun& run, const MeshTriangle* triangles, float tMin,
                              float tMax, TriangleHit& hit, uint32_t& which) {
    using namespace triangle_detail;
    __m256 t = _mm256_setzero_ps(), invDet = t, v = t, w = t;  // set only where a lane is hit
    const int mask = intersectLanes<Lanes8>(r, run.lanes(), tMin, tMax, t, invDet, v, w);
    if (mask < 0)
        return intersectTrianglesLoop(r, triangles + run.blocks[0].first, run.count(), tMin, tMax, hit, which);
    return nearestLane<Lanes8>(mask & run.laneMask(), t, invDet, v, w, hit, which);
}

#if TRAZO_HOST_AVX512
// A run of three or four blocks in one sixteen-lane test, against two eight-lane ones (AVX-512 on Zen 5, bvh_bench,
// one thread, best of 5 interleaved rounds): bunny random rays 0.99× Embree's speed against 0.95×, camera rays 1.43×
// against 1.37×; the million-triangle sphere's rows alike within this VM's noise. Closest hits only: shadow rays,
// whose pairs may stop at the first hit, went from 0.98–0.99× Embree's speed to 0.94–0.95× (the sphere).
inline bool intersectBlockQuad(const TriangleRay& r, const triangle_detail::BlockQuad& quad,
                               const MeshTriangle* triangles, float tMin, float tMax, TriangleHit& hit,
                               uint32_t& which) {
    using namespace triangle_detail;
    const TriangleBlock& last = quad.blocks[quad.four ? 3 : 2];
    const int lastLanes = quad.four ? 12 : 8;
    __m512 t = _mm512_setzero_ps(), invDet = t, v = t, w = t;  // set only where a lane is hit
    const int mask = intersectLanes<Lanes16>(r, quad, tMin, tMax, t, invDet, v, w);
    if (mask < 0)
        return intersectTrianglesLoop(r, triangles + quad.blocks[0].first, lastLanes + last.count, tMin, tMax, hit,
                                      which);
    const int laneMask = ((1 << lastLanes) - 1) | ((1 << last.count) - 1) << lastLanes;
    return nearestLane<Lanes16>(mask & laneMask, t, invDet, v, w, hit, which);
}
#endif

// Whether any of the run's triangles is hit within (tMin, tMax): triangleLeafBlocks over them.
inline bool blockRunBlocks(const TriangleRay& r, const BlockRun& run, const MeshTriangle* triangles, float tMin,
                           float tMax) {
    using namespace triangle_detail;
    __m256 t = _mm256_setzero_ps(), invDet = t, v = t, w = t;
    const int mask = intersectLanes<Lanes8>(r, AnyHitPair{run.lanes()}, tMin, tMax, t, invDet, v, w);
    if (mask >= 0) return (mask & run.laneMask()) != 0;
    return anyTriangleHit(r, triangles + run.blocks[0].first, run.count(), tMin, tMax);
}
#endif

// Whether any of the leaf's triangles[0, count) is hit within (tMin, tMax).
TRAZO_HD bool triangleLeafBlocks(const TriangleRay& r, const MeshTriangle* triangles, uint32_t count, float tMin,
                                 float tMax) {
#if TRAZO_HOST_SSE
    using namespace triangle_detail;
    __m128 t, invDet, v, w;
    const int mask = intersectLanes<Lanes4>(r, TriangleSpan{triangles, count}, tMin, tMax, t, invDet, v, w);
    if (mask >= 0) return (mask & ((1 << count) - 1)) != 0;
#endif
    return anyTriangleHit(r, triangles, count, tMin, tMax);
}

}  // namespace trazo
