// The BVH builder's SSE inner loops against their scalar forms (accel/bvh_binning.h): the same bins, the same
// SAH split and the same partition, bit for bit, so a build without SSE gives the same tree.
#include "accel/bvh_binning.h"

#include <gtest/gtest.h>

#include <cstring>
#include <utility>
#include <vector>

#include "support/counter_uniform.h"

namespace trazo {
namespace {

using namespace bvh_binning;

// Primitive boxes rich in the awkward cases: coordinates shared between boxes, flat boxes, signed zeros,
// sizes from a thousandth to ten thousand, and in a quarter of the sets a few NaN coordinates (binned to
// bin 0 by both forms).
std::vector<PrimRef> randomRefs(CounterUniform& u, uint32_t count) {
    const float scales[] = {1e-3f, 1.0f, 1e4f};
    const float scale = scales[(int)u(0.0f, 3.0f)];
    const float nanChance = u(0.0f, 1.0f) < 0.25f ? 0.01f : 0.0f;
    auto coordinate = [&]() {
        const float pick = u(0.0f, 4.0f);
        return scale * (pick < 1.0f ? std::round(u(-3.0f, 3.0f)) : (pick < 1.2f ? -0.0f : u(-3.0f, 3.0f)));
    };
    std::vector<PrimRef> refs(count);
    for (uint32_t i = 0; i < count; ++i) {
        PrimRef& r = refs[i];
        for (int a = 0; a < 3; ++a) {
            float lo = coordinate(), hi = coordinate();
            if (lo > hi) std::swap(lo, hi);
            if (u(0.0f, 1.0f) < 0.1f) lo = hi;  // flat
            if (u(0.0f, 1.0f) < nanChance) (u(0.0f, 1.0f) < 0.5f ? lo : hi) = NAN;
            r.min[a] = lo;
            r.max[a] = hi;
        }
        r.id = i;
        r.pad = 0;
    }
    return refs;
}

// The builder's mapping over the centroids' bounds (Builder::mappingFor), sometimes narrowed so that
// centroids fall below the first bin and above the last.
BinMapping randomMapping(CounterUniform& u, const PrimRef* refs, uint32_t count) {
    Aabb centroids;
    for (uint32_t i = 0; i < count; ++i) centroids.grow(centroidOf(refs[i]));
    const uint32_t binCounts[] = {4, 8, 16, kMaxBvhBins};
    BinMapping m;
    m.binCount = binCounts[(int)u(0.0f, 4.0f)];
    Vec3 e = centroids.extent();
    m.origin = centroids.min;
    if (u(0.0f, 1.0f) < 0.3f) {
        m.origin = m.origin + e * 0.25f;
        e = e * 0.5f;
    }
    for (int a = 0; a < 3; ++a) m.scale[a] = e[a] > 0.0f ? (float)m.binCount * (1.0f - 1e-6f) / e[a] : 0.0f;
    return m;
}

bool sameBits(const Aabb& a, const Aabb& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

#if TRAZO_BVH_BINNING_SSE
TEST(BvhBinning, SseBinsMatchScalarBitForBit) {
    CounterUniform u(60);
    int spread = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const std::vector<PrimRef> refs = randomRefs(u, 1 + (uint32_t)u(0.0f, 300.0f));
        const uint32_t n = (uint32_t)refs.size();
        const BinMapping m = randomMapping(u, refs.data(), n);
        BinSet scalar(m.binCount), sse(m.binCount);
        binPrimitivesScalar(refs.data(), n, m, scalar);
        binPrimitivesSse(refs.data(), n, m, sse);
        for (int a = 0; a < 3; ++a) {
            uint32_t total = 0, used = 0;
            for (uint32_t b = 0; b < m.binCount; ++b) {
                ASSERT_EQ(scalar.counts[a][b], sse.counts[a][b]) << "trial " << trial << " axis " << a << " bin " << b;
                ASSERT_EQ(0, std::memcmp(&scalar.bounds[a][b], &sse.bounds[a][b], sizeof(BinBox)))
                    << "trial " << trial << " axis " << a << " bin " << b;
                total += scalar.counts[a][b];
                used += scalar.counts[a][b] != 0;
            }
            ASSERT_EQ(total, n) << "every primitive lands in one bin of each axis";
            spread += used > 2;
        }
    }
    EXPECT_GT(spread, 3000) << "too few axes with primitives in several bins to test anything";
}

TEST(BvhBinning, SseSahSweepMatchesScalarBitForBit) {
    CounterUniform u(61);
    int found = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const std::vector<PrimRef> refs = randomRefs(u, 2 + (uint32_t)u(0.0f, 300.0f));
        const BinMapping m = randomMapping(u, refs.data(), (uint32_t)refs.size());
        BinSet bins(m.binCount);
        binPrimitivesScalar(refs.data(), (uint32_t)refs.size(), m, bins);
        SahSplit scalar, sse;  // carried over the axes, as the builder does
        for (int a = 0; a < 3; ++a) {
            sweepAxisScalar(bins, m.binCount, a, scalar);
            sweepAxisSse(bins, m.binCount, a, sse);
            ASSERT_EQ(scalar.found, sse.found) << "trial " << trial << " axis " << a;
            ASSERT_EQ(0, std::memcmp(&scalar.cost, &sse.cost, sizeof(float))) << "trial " << trial << " axis " << a;
            ASSERT_EQ(scalar.axis, sse.axis) << "trial " << trial;
            ASSERT_EQ(scalar.bin, sse.bin) << "trial " << trial;
            ASSERT_EQ(scalar.leftCount, sse.leftCount) << "trial " << trial;
        }
        found += scalar.found;
    }
    EXPECT_GT(found, 2000) << "too few splits found to test anything";
}

TEST(BvhBinning, SsePartitionMatchesScalarBitForBit) {
    CounterUniform u(62);
    int mixed = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        std::vector<PrimRef> scalarRefs = randomRefs(u, 1 + (uint32_t)u(0.0f, 300.0f));
        std::vector<PrimRef> sseRefs = scalarRefs;
        const uint32_t n = (uint32_t)scalarRefs.size();
        const uint32_t begin = (uint32_t)u(0.0f, n / 4.0f), end = n - (uint32_t)u(0.0f, n / 4.0f);
        const BinMapping m = randomMapping(u, scalarRefs.data() + begin, end - begin);
        const int axis = (int)u(0.0f, 3.0f);
        const int splitBin = (int)u(0.0f, (float)m.binCount + 1.0f);  // 0 and binCount: everything to one side
        const Partition scalar = partitionScalar(scalarRefs.data(), begin, end, m, axis, splitBin);
        const Partition sse = partitionSse(sseRefs.data(), begin, end, m, axis, splitBin);
        ASSERT_EQ(scalar.mid, sse.mid) << "trial " << trial;
        ASSERT_EQ(0, std::memcmp(scalarRefs.data(), sseRefs.data(), n * sizeof(PrimRef))) << "trial " << trial;
        ASSERT_TRUE(sameBits(scalar.leftBounds, sse.leftBounds)) << "trial " << trial;
        ASSERT_TRUE(sameBits(scalar.leftCentroids, sse.leftCentroids)) << "trial " << trial;
        ASSERT_TRUE(sameBits(scalar.rightBounds, sse.rightBounds)) << "trial " << trial;
        ASSERT_TRUE(sameBits(scalar.rightCentroids, sse.rightCentroids)) << "trial " << trial;
        for (uint32_t i = begin; i < end; ++i)
            ASSERT_EQ(m.binOf(centroidOf(scalarRefs[i])[axis], axis) < splitBin, i < scalar.mid)
                << "trial " << trial << ": primitive " << i << " on the wrong side";
        mixed += scalar.mid > begin && scalar.mid < end;
    }
    EXPECT_GT(mixed, 1500) << "too few partitions with both sides filled to test anything";
}
#else
TEST(BvhBinning, SseFormsAreX86Only) {
    GTEST_SKIP() << "this build has no SSE binning, SAH sweep or partition (not x86-64)";
}
#endif

}  // namespace
}  // namespace trazo
