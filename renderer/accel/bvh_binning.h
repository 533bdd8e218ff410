// The binned-SAH builder's inner loops (host, bvh_build.cpp): binning primitives by centroid, the SAH sweep
// over one axis's bins, and the partition at the chosen bin. Each has a scalar form and, on x86-64, an SSE
// form doing the same IEEE operations in the same order, so both build the same tree (bvh_binning_test.cpp
// compares them bit for bit); the builder takes the SSE forms where it can, as binning dominates a build.
#pragma once

#include <cmath>
#include <cstdint>
#include <utility>

#include "accel/bvh_build.h"
#include "core/aabb.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#define TRAZO_BVH_BINNING_SSE 1
#else
#define TRAZO_BVH_BINNING_SSE 0
#endif

namespace trazo {
namespace bvh_binning {

// Primitive bounds and original index packed in 32 bytes; the builder partitions these in place.
struct PrimRef {
    Vec3 min;
    uint32_t id;
    Vec3 max;
    uint32_t pad;
};

// minOf/maxOf (core/vec3.h): single SSE instructions, where fminf's NaN rules are calls; the builder never
// sees NaN bounds it must keep.
inline void growBox(Aabb& box, Vec3 lo, Vec3 hi) {
    box.min = {minOf(box.min.x, lo.x), minOf(box.min.y, lo.y), minOf(box.min.z, lo.z)};
    box.max = {maxOf(box.max.x, hi.x), maxOf(box.max.y, hi.y), maxOf(box.max.z, hi.z)};
}
inline void growBox(Aabb& box, const Aabb& b) { growBox(box, b.min, b.max); }
inline Vec3 centroidOf(const PrimRef& r) { return (r.min + r.max) * 0.5f; }

// Maps a centroid coordinate to its bin: NaN and values below the range go to bin 0, the top to the last.
struct BinMapping {
    Vec3 origin, scale;
    uint32_t binCount;
    int binOf(float c, int axis) const {
        const float f = (c - origin[axis]) * scale[axis];
        const float last = (float)(binCount - 1);
        return f > 0.0f ? (f < last ? (int)f : (int)last) : 0;
    }
};

// Only the first `binCount` bins are used and initialised: a node's bins are set up half a million times.
// (Plain floats: Vec3 and Aabb initialise their members, which would touch all kMaxBvhBins.)
// Lane 3 of lo and hi is padding (kept 0), so that a box is one aligned four-lane load.
struct alignas(16) BinBox {
    float lo[4], hi[4];
    void grow(Vec3 bMin, Vec3 bMax) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = minOf(lo[a], bMin[a]);
            hi[a] = maxOf(hi[a], bMax[a]);
        }
    }
    Aabb aabb() const {
        Aabb b;
        b.min = Vec3(lo[0], lo[1], lo[2]);
        b.max = Vec3(hi[0], hi[1], hi[2]);
        return b;
    }
};
struct BinSet {
    BinBox bounds[3][kMaxBvhBins];
    uint32_t counts[3][kMaxBvhBins];
    explicit BinSet(uint32_t binCount) {
        for (int a = 0; a < 3; ++a)
            for (uint32_t b = 0; b < binCount; ++b) {
                bounds[a][b] = BinBox{{INFINITY, INFINITY, INFINITY, 0.0f}, {-INFINITY, -INFINITY, -INFINITY, 0.0f}};
                counts[a][b] = 0;
            }
    }
};

// The cheapest SAH split found so far: bins [0, bin) of `axis` go left, `leftCount` primitives.
struct SahSplit {
    float cost = INFINITY;  // Σ A(child) · count(child) over the two children
    int axis = 0;
    int bin = 0;
    uint32_t leftCount = 0;
    bool found = false;
};

// The two children of a partition: [begin, mid) and [mid, end), with their bounds and centroid bounds.
struct Partition {
    uint32_t mid;
    Aabb leftBounds, leftCentroids, rightBounds, rightCentroids;
};

inline void binPrimitivesScalar(const PrimRef* refs, uint32_t count, const BinMapping& m, BinSet& bins) {
    for (uint32_t i = 0; i < count; ++i) {
        const PrimRef& r = refs[i];
        const Vec3 c = centroidOf(r);
        for (int a = 0; a < 3; ++a) {
            const int b = m.binOf(c[a], a);
            bins.bounds[a][b].grow(r.min, r.max);
            ++bins.counts[a][b];
        }
    }
}

// Updates `best` with the cheapest split between the bins of `axis` if it costs less.
inline void sweepAxisScalar(const BinSet& bins, uint32_t binCount, int axis, SahSplit& best) {
    float rightArea[kMaxBvhBins];
    uint32_t rightCount[kMaxBvhBins];
    Aabb box;
    uint32_t c = 0;
    for (uint32_t b = binCount - 1; b > 0; --b) {
        growBox(box, bins.bounds[axis][b].aabb());
        c += bins.counts[axis][b];
        rightArea[b] = box.surfaceArea();
        rightCount[b] = c;
    }
    box = Aabb{};
    c = 0;
    for (uint32_t b = 1; b < binCount; ++b) {
        growBox(box, bins.bounds[axis][b - 1].aabb());
        c += bins.counts[axis][b - 1];
        if (c == 0 || rightCount[b] == 0) continue;
        const float cost = box.surfaceArea() * (float)c + rightArea[b] * (float)rightCount[b];
        if (cost < best.cost) best = SahSplit{cost, axis, (int)b, c, true};
    }
}

// Partitions refs[begin, end) in place: the primitives whose centroid falls in a bin below `splitBin` of
// `axis` first. The swaps, and so the order, are the same in both forms.
inline Partition partitionScalar(PrimRef* p, uint32_t begin, uint32_t end, const BinMapping& m, int axis,
                                 int splitBin) {
    uint32_t i = begin, j = end;
    Aabb lb, lc, rb, rc;
    auto goesLeft = [&](const PrimRef& ref) { return m.binOf(centroidOf(ref)[axis], axis) < splitBin; };
    auto addLeft = [&](const PrimRef& ref) {
        growBox(lb, ref.min, ref.max);
        const Vec3 c = centroidOf(ref);
        growBox(lc, c, c);
    };
    auto addRight = [&](const PrimRef& ref) {
        growBox(rb, ref.min, ref.max);
        const Vec3 c = centroidOf(ref);
        growBox(rc, c, c);
    };
    for (;;) {
        while (i < j && goesLeft(p[i])) addLeft(p[i++]);
        while (i < j && !goesLeft(p[j - 1])) addRight(p[--j]);
        if (i >= j) break;
        std::swap(p[i], p[j - 1]);
        addLeft(p[i++]);
        addRight(p[--j]);
    }
    return Partition{i, lb, lc, rb, rc};
}

#if TRAZO_BVH_BINNING_SSE
// The same arithmetic as BinMapping::binOf in four lanes (maxps returns 0 for NaN as binOf does), with
// bin boxes grown by one minps/maxps.
inline void binPrimitivesSse(const PrimRef* refs, uint32_t count, const BinMapping& m, BinSet& bins) {
    const __m128 origin = _mm_setr_ps(m.origin.x, m.origin.y, m.origin.z, 0.0f);
    const __m128 scale = _mm_setr_ps(m.scale.x, m.scale.y, m.scale.z, 0.0f);
    const __m128 half = _mm_set1_ps(0.5f), zero = _mm_setzero_ps(), last = _mm_set1_ps((float)(m.binCount - 1));
    const __m128 xyz = _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0));  // the id lane would be a denormal
    for (uint32_t i = 0; i < count; ++i) {
        const __m128 bMin = _mm_and_ps(_mm_loadu_ps(&refs[i].min.x), xyz);
        const __m128 bMax = _mm_and_ps(_mm_loadu_ps(&refs[i].max.x), xyz);
        const __m128 f = _mm_mul_ps(_mm_sub_ps(_mm_mul_ps(_mm_add_ps(bMin, bMax), half), origin), scale);
        alignas(16) int32_t bin[4];
        _mm_store_si128((__m128i*)bin, _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(f, zero), last)));
        for (int a = 0; a < 3; ++a) {
            BinBox& box = bins.bounds[a][bin[a]];
            _mm_store_ps(box.lo, _mm_min_ps(_mm_load_ps(box.lo), bMin));
            _mm_store_ps(box.hi, _mm_max_ps(_mm_load_ps(box.hi), bMax));
            ++bins.counts[a][bin[a]];
        }
    }
}

// growBox and Aabb::surfaceArea in four lanes, the same operations in the same order.
inline void sweepAxisSse(const BinSet& bins, uint32_t binCount, int axis, SahSplit& best) {
    float rightArea[kMaxBvhBins];
    uint32_t rightCount[kMaxBvhBins];
    auto area = [](__m128 lo, __m128 hi) {
        if (_mm_movemask_ps(_mm_cmpgt_ps(lo, hi)) & 7) return 0.0f;  // empty
        const __m128 e = _mm_sub_ps(hi, lo);
        alignas(16) float p[4];  // (ex·ey, ey·ez, ez·ex, ·)
        _mm_store_ps(p, _mm_mul_ps(e, _mm_shuffle_ps(e, e, _MM_SHUFFLE(3, 0, 2, 1))));
        return 2.0f * (p[0] + p[1] + p[2]);
    };
    __m128 lo = _mm_set1_ps(INFINITY), hi = _mm_set1_ps(-INFINITY);
    uint32_t c = 0;
    for (uint32_t b = binCount - 1; b > 0; --b) {
        lo = _mm_min_ps(lo, _mm_load_ps(bins.bounds[axis][b].lo));
        hi = _mm_max_ps(hi, _mm_load_ps(bins.bounds[axis][b].hi));
        c += bins.counts[axis][b];
        rightArea[b] = area(lo, hi);
        rightCount[b] = c;
    }
    lo = _mm_set1_ps(INFINITY), hi = _mm_set1_ps(-INFINITY);
    c = 0;
    for (uint32_t b = 1; b < binCount; ++b) {
        lo = _mm_min_ps(lo, _mm_load_ps(bins.bounds[axis][b - 1].lo));
        hi = _mm_max_ps(hi, _mm_load_ps(bins.bounds[axis][b - 1].hi));
        c += bins.counts[axis][b - 1];
        if (c == 0 || rightCount[b] == 0) continue;
        const float cost = area(lo, hi) * (float)c + rightArea[b] * (float)rightCount[b];
        if (cost < best.cost) best = SahSplit{cost, axis, (int)b, c, true};
    }
}

// binOf's arithmetic in four lanes, as binPrimitivesSse does it, and the boxes grown by minps/maxps
// (which are minOf/maxOf: "a < b ? a : b").
inline Partition partitionSse(PrimRef* p, uint32_t begin, uint32_t end, const BinMapping& m, int axis,
                              int splitBin) {
    uint32_t i = begin, j = end;
    const __m128 origin = _mm_setr_ps(m.origin.x, m.origin.y, m.origin.z, 0.0f);
    const __m128 scale = _mm_setr_ps(m.scale.x, m.scale.y, m.scale.z, 0.0f);
    const __m128 half = _mm_set1_ps(0.5f), zero = _mm_setzero_ps(), last = _mm_set1_ps((float)(m.binCount - 1));
    const __m128 xyz = _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0));
    const __m128 inf = _mm_set1_ps(INFINITY), negInf = _mm_set1_ps(-INFINITY);
    __m128 lbMin = inf, lbMax = negInf, lcMin = inf, lcMax = negInf;
    __m128 rbMin = inf, rbMax = negInf, rcMin = inf, rcMax = negInf;
    struct Lanes {
        __m128 lo, hi, c;
        bool left;
    };
    auto look = [&](const PrimRef& ref) {
        Lanes l;
        l.lo = _mm_and_ps(_mm_loadu_ps(&ref.min.x), xyz);
        l.hi = _mm_and_ps(_mm_loadu_ps(&ref.max.x), xyz);
        l.c = _mm_mul_ps(_mm_add_ps(l.lo, l.hi), half);
        alignas(16) int32_t bin[4];
        _mm_store_si128((__m128i*)bin,
                        _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(_mm_mul_ps(_mm_sub_ps(l.c, origin), scale), zero), last)));
        l.left = bin[axis] < splitBin;
        return l;
    };
    auto addLeft = [&](const Lanes& l) {
        lbMin = _mm_min_ps(lbMin, l.lo), lbMax = _mm_max_ps(lbMax, l.hi);
        lcMin = _mm_min_ps(lcMin, l.c), lcMax = _mm_max_ps(lcMax, l.c);
    };
    auto addRight = [&](const Lanes& l) {
        rbMin = _mm_min_ps(rbMin, l.lo), rbMax = _mm_max_ps(rbMax, l.hi);
        rcMin = _mm_min_ps(rcMin, l.c), rcMax = _mm_max_ps(rcMax, l.c);
    };
    for (;;) {
        Lanes a{}, b{};
        while (i < j && (a = look(p[i])).left) addLeft(a), ++i;
        while (i < j && !(b = look(p[j - 1])).left) addRight(b), --j;
        if (i >= j) break;
        std::swap(p[i], p[j - 1]);
        addLeft(b), ++i;  // b (now at i) goes left, a (now at j - 1) goes right
        addRight(a), --j;
    }
    auto toVec3 = [](__m128 v) {
        alignas(16) float f[4];
        _mm_store_ps(f, v);
        return Vec3(f[0], f[1], f[2]);
    };
    return Partition{i, Aabb{toVec3(lbMin), toVec3(lbMax)}, Aabb{toVec3(lcMin), toVec3(lcMax)},
                     Aabb{toVec3(rbMin), toVec3(rbMax)}, Aabb{toVec3(rcMin), toVec3(rcMax)}};
}
#endif

// The forms the builder runs. binPrimitives stays out of line: inlined into chooseSplit it slows the build
// (bvh_bench's "Trazo build").
__attribute__((noinline)) inline void binPrimitives(const PrimRef* refs, uint32_t count, const BinMapping& m,
                                                    BinSet& bins) {
#if TRAZO_BVH_BINNING_SSE
    binPrimitivesSse(refs, count, m, bins);
#else
    binPrimitivesScalar(refs, count, m, bins);
#endif
}
inline void sweepAxis(const BinSet& bins, uint32_t binCount, int axis, SahSplit& best) {
#if TRAZO_BVH_BINNING_SSE
    sweepAxisSse(bins, binCount, axis, best);
#else
    sweepAxisScalar(bins, binCount, axis, best);
#endif
}
inline Partition partitionPrimitives(PrimRef* p, uint32_t begin, uint32_t end, const BinMapping& m, int axis,
                                     int splitBin) {
#if TRAZO_BVH_BINNING_SSE
    return partitionSse(p, begin, end, m, axis, splitBin);
#else
    return partitionScalar(p, begin, end, m, axis, splitBin);
#endif
}

}  // namespace bvh_binning
}  // namespace trazo
