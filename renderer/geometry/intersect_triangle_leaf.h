// A BVH leaf's triangles (at most four) against one ray (host and device): the nearest hit, and whether any
// hits. The device loops over intersectTriangle; the host tests the four at once with SSE, the same IEEE
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

// Up to four consecutive triangles of a mesh transposed for four-lane tests: v[k][axis][lane] is vertex k of
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
inline const TriangleBlock& transposedLeaf(const TriangleBlock& block) { return block; }

// A block as the any-hit test reads it: an intersect4 of its own, so the closest-hit test's keeps one caller
// (with two, GCC called it out of line from the closest-hit traversal: bvh_bench's bunny primary rays 4.5 %
// slower; forcing it inline instead cost the four-wide any-hit path).
struct AnyHitBlock {
    const TriangleBlock& block;
};
inline const TriangleBlock& transposedLeaf(AnyHitBlock leaf) { return leaf.block; }

// Vertex k's coordinates on one axis, four lanes, from either form of a transposed leaf.
inline __m128 vertexLanes(const Triangles4& tri, int k, int axis) { return tri.v[k][axis]; }
inline __m128 vertexLanes(const TriangleBlock& block, int k, int axis) { return _mm_load_ps(block.v[k][axis]); }

// intersectSheared for four triangles (a TriangleSpan or a TriangleBlock). Returns the mask of lanes hit within
// (tMin, tMax), with t and the reciprocal determinant per lane, or −1 when a lane has an edge function of
// exactly zero: the caller then falls back to the scalar test, which re-evaluates it in double.
// A span is transposed here rather than by the caller, so its vertices stay in registers (any-hit traversal:
// 3-4 % fewer rays a second the other way, bvh_bench).
template <int KZ, class Leaf>
inline int intersect4Along(const TriangleRay& r, const Leaf& leaf, float tMin, float tMax, __m128& t, __m128& invDet,
                           __m128& v, __m128& w) {
    constexpr int KX = KZ == 2 ? 0 : KZ + 1, KY = KX == 2 ? 0 : KX + 1;
    const auto& tri = transposedLeaf(leaf);
    const __m128 ox = _mm_set1_ps(r.origin[KX]), oy = _mm_set1_ps(r.origin[KY]), oz = _mm_set1_ps(r.origin[KZ]);
    const __m128 sx = _mm_set1_ps(r.sx), sy = _mm_set1_ps(r.sy), sz = _mm_set1_ps(r.sz);
    __m128 x[3], y[3], z[3];
    for (int k = 0; k < 3; ++k) {
        const __m128 px = _mm_sub_ps(vertexLanes(tri, k, KX), ox), py = _mm_sub_ps(vertexLanes(tri, k, KY), oy);
        z[k] = _mm_sub_ps(vertexLanes(tri, k, KZ), oz);
        x[k] = _mm_sub_ps(px, _mm_mul_ps(sx, z[k]));
        y[k] = _mm_sub_ps(py, _mm_mul_ps(sy, z[k]));
    }
    // triangleEdge(c, b), (a, c), (b, a): px·qy − py·qx.
    const __m128 u = _mm_sub_ps(_mm_mul_ps(x[2], y[1]), _mm_mul_ps(y[2], x[1]));
    v = _mm_sub_ps(_mm_mul_ps(x[0], y[2]), _mm_mul_ps(y[0], x[2]));
    w = _mm_sub_ps(_mm_mul_ps(x[1], y[0]), _mm_mul_ps(y[1], x[0]));
    const __m128 zero = _mm_setzero_ps();
    const __m128 anyZero = _mm_or_ps(_mm_cmpeq_ps(u, zero), _mm_or_ps(_mm_cmpeq_ps(v, zero), _mm_cmpeq_ps(w, zero)));
    if (_mm_movemask_ps(anyZero)) return -1;
    const __m128 anyNegative = _mm_or_ps(_mm_cmplt_ps(u, zero), _mm_or_ps(_mm_cmplt_ps(v, zero), _mm_cmplt_ps(w, zero)));
    const __m128 anyPositive = _mm_or_ps(_mm_cmpgt_ps(u, zero), _mm_or_ps(_mm_cmpgt_ps(v, zero), _mm_cmpgt_ps(w, zero)));
    const __m128 mixedSigns = _mm_and_ps(anyNegative, anyPositive);
    if (_mm_movemask_ps(mixedSigns) == 0xf) return 0;  // most leaves a ray reaches: no division needed
    const __m128 det = _mm_add_ps(_mm_add_ps(u, v), w);
    const __m128 tScaled = _mm_add_ps(_mm_add_ps(_mm_mul_ps(u, _mm_mul_ps(sz, z[0])), _mm_mul_ps(v, _mm_mul_ps(sz, z[1]))),
                                      _mm_mul_ps(w, _mm_mul_ps(sz, z[2])));
    invDet = _mm_div_ps(_mm_set1_ps(1.0f), det);
    t = _mm_mul_ps(tScaled, invDet);
    // A lane with mixed signs or det = 0 misses; so does a NaN t (the comparisons fail).
    const __m128 inRange = _mm_and_ps(_mm_cmpgt_ps(t, _mm_set1_ps(tMin)), _mm_cmplt_ps(t, _mm_set1_ps(tMax)));
    const __m128 hit = _mm_andnot_ps(_mm_or_ps(mixedSigns, _mm_cmpeq_ps(det, zero)), inRange);
    return _mm_movemask_ps(hit);
}

template <class Leaf>
inline int intersect4(const TriangleRay& r, const Leaf& leaf, float tMin, float tMax, __m128& t, __m128& invDet,
                      __m128& v, __m128& w) {
    if (r.kz == 2) return intersect4Along<2>(r, leaf, tMin, tMax, t, invDet, v, w);
    if (r.kz == 0) return intersect4Along<0>(r, leaf, tMin, tMax, t, invDet, v, w);
    return intersect4Along<1>(r, leaf, tMin, tMax, t, invDet, v, w);
}

// The nearest of the lanes in `mask` (the first of equal ones), as intersectTrianglesLoop would report it.
inline bool nearestLane(int mask, __m128 t, __m128 invDet, __m128 v, __m128 w, TriangleHit& hit, uint32_t& which) {
    if (!mask) return false;
    alignas(16) float ts[4], invDets[4], vs[4], ws[4];
    _mm_store_ps(ts, t), _mm_store_ps(invDets, invDet), _mm_store_ps(vs, v), _mm_store_ps(ws, w);
    int best = -1;
    for (int k = 0; k < 4; ++k)
        if ((mask & (1 << k)) && (best < 0 || ts[k] < ts[best])) best = k;
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
    int mask = intersect4(r, TriangleSpan{triangles, count}, tMin, tMax, t, invDet, v, w);
    if (mask < 0) return intersectTrianglesLoop(r, triangles, count, tMin, tMax, hit, which);
    return nearestLane(mask & ((1 << count) - 1), t, invDet, v, w, hit, which);
#else
    return intersectTrianglesLoop(r, triangles, count, tMin, tMax, hit, which);
#endif
}

#if TRAZO_HOST_SSE
// intersectTriangleLeaf over a block's triangles (the mesh's from block.first), the same answer bit for bit.
inline bool intersectTriangleBlock(const TriangleRay& r, const TriangleBlock& block, const MeshTriangle* triangles,
                                   uint32_t count, float tMin, float tMax, TriangleHit& hit, uint32_t& which) {
    using namespace triangle_detail;
    __m128 t, invDet, v, w;
    const int mask = intersect4(r, block, tMin, tMax, t, invDet, v, w);
    if (mask < 0) return intersectTrianglesLoop(r, triangles + block.first, count, tMin, tMax, hit, which);
    return nearestLane(mask & ((1 << count) - 1), t, invDet, v, w, hit, which);
}

// Whether any of the block's triangles is hit within (tMin, tMax): triangleLeafBlocks over them.
inline bool triangleBlockBlocks(const TriangleRay& r, const TriangleBlock& block, const MeshTriangle* triangles,
                                float tMin, float tMax) {
    using namespace triangle_detail;
    __m128 t, invDet, v, w;
    const int mask = intersect4(r, AnyHitBlock{block}, tMin, tMax, t, invDet, v, w);
    if (mask >= 0) return (mask & ((1 << block.count) - 1)) != 0;
    return anyTriangleHit(r, triangles + block.first, block.count, tMin, tMax);
}
#endif

// Whether any of the leaf's triangles[0, count) is hit within (tMin, tMax).
TRAZO_HD bool triangleLeafBlocks(const TriangleRay& r, const MeshTriangle* triangles, uint32_t count, float tMin,
                                 float tMax) {
#if TRAZO_HOST_SSE
    using namespace triangle_detail;
    __m128 t, invDet, v, w;
    const int mask = intersect4(r, TriangleSpan{triangles, count}, tMin, tMax, t, invDet, v, w);
    if (mask >= 0) return (mask & ((1 << count) - 1)) != 0;
#endif
    return anyTriangleHit(r, triangles, count, tMin, tMax);
}

}  // namespace trazo
