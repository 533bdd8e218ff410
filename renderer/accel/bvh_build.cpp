// Binned-SAH BVH builder (host). The top of the tree is split level by level, a level's nodes on several
// threads (or, while a level has fewer nodes than threads, each node's binning spread over them); the
// subtrees below a fixed size become tasks built on the pool's threads into their own arrays, concatenated
// at the end in task order, so the layout does not depend on the thread count.
#include "accel/bvh_build.h"

#include <algorithm>
#include <cassert>
#include <functional>

#include "core/thread_pool.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace trazo {
namespace {

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

struct Range {
    uint32_t begin = 0, end = 0, depth = 0;
    Aabb bounds, centroids;
    uint32_t count() const { return end - begin; }
};

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

#if defined(__SSE2__)
// The same arithmetic as BinMapping::binOf in four lanes (maxps returns 0 for NaN as binOf does), with
// bin boxes grown by one minps/maxps: binning dominates the build.
void binPrimitives(const PrimRef* refs, uint32_t count, const BinMapping& m, BinSet& bins) {
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
#else
void binPrimitives(const PrimRef* refs, uint32_t count, const BinMapping& m, BinSet& bins) {
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
#endif

enum class SplitKind { Leaf, Sah, Median };
struct Split {
    SplitKind kind = SplitKind::Leaf;
    int axis = 0;
    int bin = 0;  // SAH: bins [0, bin) go left
};

class Builder {
public:
    Builder(std::vector<PrimRef>& refs, const BvhBuildOptions& options, ThreadPool& pool, unsigned threads)
        : refs_(refs), options_(options), pool_(pool), threads_(threads) {
        // Independent of the thread count, so the layout is too; ~64-128 tasks balance well up to 16+ threads.
        taskThreshold_ = std::max<uint32_t>(4096, (uint32_t)(refs.size() / 64));
    }

    // Splits one node of the top of the tree: its split and partition, without touching the node arrays
    // (several nodes of one level are split at once, on different threads).
    struct TopSplit {
        bool leaf = true;
        Range left, right;
    };
    TopSplit splitTop(const Range& r, bool parallelBinning) {
        TopSplit out;
        const Split split = chooseSplit(r, parallelBinning);
        if (split.kind == SplitKind::Leaf) return out;
        out.leaf = false;
        if (split.kind == SplitKind::Sah) partitionSah(r, split, out.left, out.right);
        else partitionMedian(r, out.left, out.right);
        return out;
    }

    // The top of the tree, one level at a time: a level's nodes above the task size are split in
    // parallel (one node per thread, or one node's binning over all threads when the level has fewer
    // nodes than threads); their children are numbered in level order, so the layout does not depend on
    // the thread count. Nodes at or below the task size become tasks, in the order they are met.
    void buildTop(std::vector<BvhNode>& out, const Range& root, std::vector<Range>& tasks,
                  std::vector<uint32_t>& taskSlots) {
        std::vector<std::pair<Range, uint32_t>> level{{root, 0u}}, big, next;  // (range, node index)
        std::vector<TopSplit> splits;
        while (!level.empty()) {
            big.clear();
            for (const auto& [r, slot] : level) {
                if (r.count() <= taskThreshold_) {
                    tasks.push_back(r);
                    taskSlots.push_back(slot);
                } else {
                    big.push_back({r, slot});
                }
            }
            splits.assign(big.size(), TopSplit{});
            if (big.size() < threads_) {
                for (size_t i = 0; i < big.size(); ++i) splits[i] = splitTop(big[i].first, true);
            } else {
                pool_.parallelFor(
                    big.size(), 1, [&](size_t i, size_t) { splits[i] = splitTop(big[i].first, false); }, threads_);
            }
            next.clear();
            for (size_t i = 0; i < big.size(); ++i) {
                const Range& r = big[i].first;
                if (splits[i].leaf) {
                    out[big[i].second] = BvhNode{r.bounds.min, r.begin, r.bounds.max, r.count()};
                    continue;
                }
                const uint32_t child = (uint32_t)out.size();
                out.resize(out.size() + 2);
                out[big[i].second] = BvhNode{r.bounds.min, child, r.bounds.max, 0};
                next.push_back({splits[i].left, child});
                next.push_back({splits[i].right, child + 1});
            }
            level.swap(next);
        }
    }

    void buildSubtree(std::vector<BvhNode>& out, uint32_t nodeIndex, const Range& r) {
        Range left, right;
        if (!splitNode(out, nodeIndex, r, false, left, right)) return;
        const uint32_t child = out[nodeIndex].firstOrChild;
        buildSubtree(out, child, left);
        buildSubtree(out, child + 1, right);
    }

private:
    // Writes out[nodeIndex] as a leaf (returns false) or as an interior node with two fresh children
    // appended to `out` (returns true, with the children's ranges).
    bool splitNode(std::vector<BvhNode>& out, uint32_t nodeIndex, const Range& r, bool parallel, Range& left,
                   Range& right) {
        const Split split = chooseSplit(r, parallel);
        if (split.kind == SplitKind::Leaf) {
            out[nodeIndex] = BvhNode{r.bounds.min, r.begin, r.bounds.max, r.count()};
            return false;
        }
        if (split.kind == SplitKind::Sah) partitionSah(r, split, left, right);
        else partitionMedian(r, left, right);
        const uint32_t child = (uint32_t)out.size();
        out.resize(out.size() + 2);
        out[nodeIndex] = BvhNode{r.bounds.min, child, r.bounds.max, 0};
        return true;
    }

    BinMapping mappingFor(const Range& r) const {
        BinMapping m;
        m.origin = r.centroids.min;
        // Fewer bins than primitives buys nothing: small nodes bin faster.
        m.binCount = std::min(options_.binCount, std::max(4u, r.count()));
        const Vec3 e = r.centroids.extent();
        for (int a = 0; a < 3; ++a)  // the (1 − ε) keeps the largest centroid inside the last bin
            m.scale[a] = e[a] > 0.0f ? (float)m.binCount * (1.0f - 1e-6f) / e[a] : 0.0f;
        return m;
    }

    void binRange(const Range& r, const BinMapping& m, bool parallel, BinSet& bins) const {
        const unsigned parts = parallel && r.count() >= 32768 ? threads_ : 1;
        if (parts <= 1) {
            binPrimitives(refs_.data() + r.begin, r.count(), m, bins);
            return;
        }
        std::vector<BinSet> partial(parts, BinSet(m.binCount));
        const uint32_t chunk = (r.count() + parts - 1) / parts;
        pool_.parallelFor(
            parts, 1,
            [&](size_t p, size_t) {
                const uint32_t b = r.begin + std::min<uint32_t>(r.count(), uint32_t(p) * chunk);
                const uint32_t e = r.begin + std::min<uint32_t>(r.count(), uint32_t(p + 1) * chunk);
                binPrimitives(refs_.data() + b, e - b, m, partial[p]);
            },
            threads_);
        // Min/max and integer sums: the merged bins are exact whatever the chunking.
        for (const BinSet& s : partial)
            for (int a = 0; a < 3; ++a)
                for (uint32_t b = 0; b < m.binCount; ++b) {
                    bins.bounds[a][b].grow(Vec3(s.bounds[a][b].lo[0], s.bounds[a][b].lo[1], s.bounds[a][b].lo[2]),
                                           Vec3(s.bounds[a][b].hi[0], s.bounds[a][b].hi[1], s.bounds[a][b].hi[2]));
                    bins.counts[a][b] += s.counts[a][b];
                }
    }

    Split chooseSplit(const Range& r, bool parallel) const {
        const uint32_t n = r.count();
        const uint32_t remaining = kMaxBvhDepth - r.depth;
        if (n == 1 || remaining == 0) return {};  // the depth rule below guarantees n ≤ maxLeafSize here
        // Children must stay small enough to finish by median splits within the depth left.
        const uint64_t childLimit =
            remaining - 1 >= 32 ? UINT64_MAX : (uint64_t)options_.maxLeafSize << (remaining - 1);

        Split best;
        float bestCost = INFINITY;
        uint32_t bestLeft = 0;
        const BinMapping m = mappingFor(r);
        if (m.scale.x > 0.0f || m.scale.y > 0.0f || m.scale.z > 0.0f) {
            BinSet bins(m.binCount);
            binRange(r, m, parallel, bins);
            const uint32_t k = m.binCount;
            for (int a = 0; a < 3; ++a) {
                if (m.scale[a] == 0.0f) continue;
                float rightArea[kMaxBvhBins];
                uint32_t rightCount[kMaxBvhBins];
#if defined(__SSE2__)
                // growBox and Aabb::surfaceArea in four lanes, the same operations in the same order.
                auto area = [](__m128 lo, __m128 hi) {
                    if (_mm_movemask_ps(_mm_cmpgt_ps(lo, hi)) & 7) return 0.0f;  // empty
                    const __m128 e = _mm_sub_ps(hi, lo);
                    alignas(16) float p[4];  // (ex·ey, ey·ez, ez·ex, ·)
                    _mm_store_ps(p, _mm_mul_ps(e, _mm_shuffle_ps(e, e, _MM_SHUFFLE(3, 0, 2, 1))));
                    return 2.0f * (p[0] + p[1] + p[2]);
                };
                __m128 lo = _mm_set1_ps(INFINITY), hi = _mm_set1_ps(-INFINITY);
                uint32_t c = 0;
                for (uint32_t b = k - 1; b > 0; --b) {
                    lo = _mm_min_ps(lo, _mm_load_ps(bins.bounds[a][b].lo));
                    hi = _mm_max_ps(hi, _mm_load_ps(bins.bounds[a][b].hi));
                    c += bins.counts[a][b];
                    rightArea[b] = area(lo, hi);
                    rightCount[b] = c;
                }
                lo = _mm_set1_ps(INFINITY), hi = _mm_set1_ps(-INFINITY);
                c = 0;
                for (uint32_t b = 1; b < k; ++b) {
                    lo = _mm_min_ps(lo, _mm_load_ps(bins.bounds[a][b - 1].lo));
                    hi = _mm_max_ps(hi, _mm_load_ps(bins.bounds[a][b - 1].hi));
                    c += bins.counts[a][b - 1];
                    if (c == 0 || rightCount[b] == 0) continue;
                    const float cost = area(lo, hi) * (float)c + rightArea[b] * (float)rightCount[b];
                    if (cost < bestCost) {
                        bestCost = cost;
                        best = Split{SplitKind::Sah, a, (int)b};
                        bestLeft = c;
                    }
                }
#else
                Aabb box;
                uint32_t c = 0;
                for (uint32_t b = k - 1; b > 0; --b) {
                    growBox(box, bins.bounds[a][b].aabb());
                    c += bins.counts[a][b];
                    rightArea[b] = box.surfaceArea();
                    rightCount[b] = c;
                }
                box = Aabb{};
                c = 0;
                for (uint32_t b = 1; b < k; ++b) {
                    growBox(box, bins.bounds[a][b - 1].aabb());
                    c += bins.counts[a][b - 1];
                    if (c == 0 || rightCount[b] == 0) continue;
                    const float cost = box.surfaceArea() * (float)c + rightArea[b] * (float)rightCount[b];
                    if (cost < bestCost) {
                        bestCost = cost;
                        best = Split{SplitKind::Sah, a, (int)b};
                        bestLeft = c;
                    }
                }
#endif
            }
        }
        const bool haveSah = best.kind == SplitKind::Sah;
        if (n <= options_.maxLeafSize) {
            const float area = r.bounds.surfaceArea();
            const float splitCost = haveSah && area > 0.0f
                                        ? options_.traversalCost + options_.intersectionCost * bestCost / area
                                        : INFINITY;
            if (!haveSah || options_.intersectionCost * (float)n <= splitCost) return {};
        }
        if (haveSah && bestLeft <= childLimit && n - bestLeft <= childLimit) return best;
        return Split{SplitKind::Median, 0, 0};
    }

    static void finishRange(Range& child, uint32_t begin, uint32_t end, uint32_t depth) {
        child.begin = begin;
        child.end = end;
        child.depth = depth;
    }

    void partitionSah(const Range& r, const Split& s, Range& left, Range& right) {
        const BinMapping m = mappingFor(r);
        PrimRef* p = refs_.data();
        uint32_t i = r.begin, j = r.end;
#if defined(__SSE2__)
        // binOf's arithmetic in four lanes, as binPrimitives does it, and the boxes grown by minps/maxps
        // (which are minOf/maxOf: "a < b ? a : b"), so the result is the scalar loop's bit for bit.
        const __m128 origin = _mm_setr_ps(m.origin.x, m.origin.y, m.origin.z, 0.0f);
        const __m128 scale = _mm_setr_ps(m.scale.x, m.scale.y, m.scale.z, 0.0f);
        const __m128 half = _mm_set1_ps(0.5f), zero = _mm_setzero_ps(), last = _mm_set1_ps((float)(m.binCount - 1));
        const __m128 xyz = _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0));
        const __m128 inf = _mm_set1_ps(INFINITY), negInf = _mm_set1_ps(-INFINITY);
        __m128 lbMin = inf, lbMax = negInf, lcMin = inf, lcMax = negInf;
        __m128 rbMin = inf, rbMax = negInf, rcMin = inf, rcMax = negInf;
        const int axis = s.axis, splitBin = s.bin;
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
            addLeft(b), ++i;   // b (now at i) goes left, a (now at j - 1) goes right
            addRight(a), --j;
        }
        auto toVec3 = [](__m128 v) {
            alignas(16) float f[4];
            _mm_store_ps(f, v);
            return Vec3(f[0], f[1], f[2]);
        };
        finishRange(left, r.begin, i, r.depth + 1);
        finishRange(right, i, r.end, r.depth + 1);
        left.bounds = Aabb{toVec3(lbMin), toVec3(lbMax)}, left.centroids = Aabb{toVec3(lcMin), toVec3(lcMax)};
        right.bounds = Aabb{toVec3(rbMin), toVec3(rbMax)}, right.centroids = Aabb{toVec3(rcMin), toVec3(rcMax)};
#else
        Aabb lb, lc, rb, rc;
        auto goesLeft = [&](const PrimRef& ref) { return m.binOf(centroidOf(ref)[s.axis], s.axis) < s.bin; };
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
        finishRange(left, r.begin, i, r.depth + 1);
        finishRange(right, i, r.end, r.depth + 1);
        left.bounds = lb, left.centroids = lc, right.bounds = rb, right.centroids = rc;
#endif
    }

    // Object median along the widest centroid axis; ties broken by original index so it is deterministic.
    void partitionMedian(const Range& r, Range& left, Range& right) {
        const Vec3 e = r.centroids.extent();
        const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
        const uint32_t mid = r.begin + r.count() / 2;
        std::nth_element(refs_.begin() + r.begin, refs_.begin() + mid, refs_.begin() + r.end,
                         [axis](const PrimRef& a, const PrimRef& b) {
                             const float ca = a.min[axis] + a.max[axis], cb = b.min[axis] + b.max[axis];
                             return ca < cb || (ca == cb && a.id < b.id);
                         });
        finishRange(left, r.begin, mid, r.depth + 1);
        finishRange(right, mid, r.end, r.depth + 1);
        for (Range* c : {&left, &right}) {
            for (uint32_t i = c->begin; i < c->end; ++i) {
                growBox(c->bounds, refs_[i].min, refs_[i].max);
                const Vec3 cc = centroidOf(refs_[i]);
                growBox(c->centroids, cc, cc);
            }
        }
    }

    std::vector<PrimRef>& refs_;
    const BvhBuildOptions& options_;
    ThreadPool& pool_;
    unsigned threads_;  // how many threads may work at once; the work's split depends on it, never the tree
    uint32_t taskThreshold_;
};

}  // namespace

Bvh buildBvh(const std::vector<Aabb>& primitiveBounds, const BvhBuildOptions& options) {
    return buildBvh((uint32_t)primitiveBounds.size(), [&](uint32_t i) { return primitiveBounds[i]; }, options);
}

Bvh buildBvh(uint32_t n, const std::function<Aabb(uint32_t)>& boundsOf, const BvhBuildOptions& optionsIn) {
    Bvh bvh;
    if (n == 0) return bvh;
    BvhBuildOptions options = optionsIn;
    options.maxLeafSize = std::max(1u, options.maxLeafSize);
    options.binCount = std::clamp(options.binCount, 2u, kMaxBvhBins);
    ThreadPool& pool = options.pool ? *options.pool : sharedThreadPool();
    const unsigned threads = options.threads ? options.threads : pool.threadCount();

    // The references, in chunks over the threads; the root's boxes are merged from the chunks' (exact:
    // min and max).
    std::vector<PrimRef> refs(n);
    Range root;
    root.end = n;
    {
        const unsigned parts = n >= 65536 ? threads : 1;
        std::vector<Range> partial(parts);
        auto fill = [&](size_t p, size_t) {
            const uint32_t chunk = (n + parts - 1) / parts;
            const uint32_t b = std::min<uint32_t>(n, uint32_t(p) * chunk), e = std::min<uint32_t>(n, uint32_t(p + 1) * chunk);
            Range& part = partial[p];
            for (uint32_t i = b; i < e; ++i) {
                const Aabb box = boundsOf(i);
                refs[i] = PrimRef{box.min, i, box.max, 0};
                growBox(part.bounds, box.min, box.max);
                const Vec3 c = centroidOf(refs[i]);
                growBox(part.centroids, c, c);
            }
        };
        pool.parallelFor(parts, 1, fill, threads);
        for (const Range& part : partial) {
            growBox(root.bounds, part.bounds);
            growBox(root.centroids, part.centroids);
        }
    }

    Builder builder(refs, options, pool, threads);
    std::vector<BvhNode> top(1);
    std::vector<Range> tasks;
    std::vector<uint32_t> taskSlots;
    builder.buildTop(top, root, tasks, taskSlots);

    // Largest tasks first so the last ones to finish are small.
    std::vector<uint32_t> schedule(tasks.size());
    for (uint32_t i = 0; i < schedule.size(); ++i) schedule[i] = i;
    std::stable_sort(schedule.begin(), schedule.end(),
                     [&](uint32_t a, uint32_t b) { return tasks[a].count() > tasks[b].count(); });
    // Each subtree's nodes are reserved here, on the calling thread: memory a worker allocates stays in its
    // own malloc arena, whose pages glibc keeps after they are freed.
    std::vector<std::vector<BvhNode>> subtrees(tasks.size());
    for (size_t t = 0; t < tasks.size(); ++t) {
        subtrees[t].reserve(2 * tasks[t].count());
        subtrees[t].resize(1);
    }
    pool.parallelFor(
        schedule.size(), 1, [&](size_t k, size_t) { builder.buildSubtree(subtrees[schedule[k]], 0, tasks[schedule[k]]); },
        threads);

    // Subtree t's local node k ≥ 1 lands at base + k − 1; its root (local 0) replaces its slot in `top`.
    size_t total = top.size();
    for (const auto& s : subtrees) total += s.size() - 1;
    bvh.nodes = std::move(top);
    bvh.nodes.reserve(total);
    for (size_t t = 0; t < subtrees.size(); ++t) {
        const uint32_t base = (uint32_t)bvh.nodes.size();
        auto relocate = [base](BvhNode node) {
            if (node.primCount == 0) node.firstOrChild += base - 1;
            return node;
        };
        std::vector<BvhNode>& s = subtrees[t];
        bvh.nodes[taskSlots[t]] = relocate(s[0]);
        for (size_t k = 1; k < s.size(); ++k) bvh.nodes.push_back(relocate(s[k]));
        std::vector<BvhNode>().swap(s);  // freed as it is copied: the peak holds one copy of the nodes
    }
    std::vector<std::vector<BvhNode>>().swap(subtrees);

    bvh.primitiveOrder.resize(n);
    for (uint32_t i = 0; i < n; ++i) bvh.primitiveOrder[i] = refs[i].id;
    return bvh;
}

float bvhSahCost(const Bvh& bvh, const BvhBuildOptions& options) {
    if (bvh.nodes.empty()) return 0.0f;
    auto area = [](const BvhNode& node) {
        Aabb b;
        b.min = node.boundsMin;
        b.max = node.boundsMax;
        return (double)b.surfaceArea();
    };
    const double rootArea = area(bvh.nodes[0]);
    double cost = 0.0;
    for (const BvhNode& node : bvh.nodes)
        cost += area(node) * (node.primCount == 0 ? options.traversalCost : options.intersectionCost * node.primCount);
    return rootArea > 0.0 ? (float)(cost / rootArea) : 0.0f;
}

uint32_t bvhDepth(const Bvh& bvh) {
    if (bvh.nodes.empty()) return 0;
    uint32_t deepest = 0;
    std::vector<std::pair<uint32_t, uint32_t>> stack{{0, 0}};
    while (!stack.empty()) {
        const auto [index, depth] = stack.back();
        stack.pop_back();
        const BvhNode& node = bvh.nodes[index];
        if (node.primCount != 0) {
            deepest = std::max(deepest, depth);
        } else {
            stack.push_back({node.firstOrChild, depth + 1});
            stack.push_back({node.firstOrChild + 1, depth + 1});
        }
    }
    return deepest;
}

}  // namespace trazo
