// Binned-SAH BVH builder (host). The top of the tree is split level by level, a level's nodes on several
// threads (or, while a level has fewer nodes than threads, each node's binning spread over them); the
// subtrees below a fixed size become tasks built on the pool's threads into their own arrays, concatenated
// at the end in task order, so the layout does not depend on the thread count.
#include "accel/bvh_build.h"

#include <algorithm>
#include <cassert>
#include <functional>

#include "accel/bvh_binning.h"
#include "core/thread_pool.h"

namespace trazo {
namespace {

using namespace bvh_binning;

struct Range {
    uint32_t begin = 0, end = 0, depth = 0;
    Aabb bounds, centroids;
    uint32_t count() const { return end - begin; }
};

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

        SahSplit sah;
        const BinMapping m = mappingFor(r);
        if (m.scale.x > 0.0f || m.scale.y > 0.0f || m.scale.z > 0.0f) {
            BinSet bins(m.binCount);
            binRange(r, m, parallel, bins);
            for (int a = 0; a < 3; ++a)
                if (m.scale[a] != 0.0f) sweepAxis(bins, m.binCount, a, sah);
        }
        if (n <= options_.maxLeafSize) {
            const float area = r.bounds.surfaceArea();
            const float splitCost = sah.found && area > 0.0f
                                        ? options_.traversalCost + options_.intersectionCost * sah.cost / area
                                        : INFINITY;
            if (!sah.found || options_.intersectionCost * (float)n <= splitCost) return {};
        }
        if (sah.found && sah.leftCount <= childLimit && n - sah.leftCount <= childLimit)
            return Split{SplitKind::Sah, sah.axis, sah.bin};
        return Split{SplitKind::Median, 0, 0};
    }

    static void finishRange(Range& child, uint32_t begin, uint32_t end, uint32_t depth) {
        child.begin = begin;
        child.end = end;
        child.depth = depth;
    }

    void partitionSah(const Range& r, const Split& s, Range& left, Range& right) {
        const Partition p = partitionPrimitives(refs_.data(), r.begin, r.end, mappingFor(r), s.axis, s.bin);
        finishRange(left, r.begin, p.mid, r.depth + 1);
        finishRange(right, p.mid, r.end, r.depth + 1);
        left.bounds = p.leftBounds, left.centroids = p.leftCentroids;
        right.bounds = p.rightBounds, right.centroids = p.rightCentroids;
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
