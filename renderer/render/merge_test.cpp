// Merging partial files: fingerprints, overlaps and gaps by number, --allow-gaps, order independence, and a
// seed scene split in 4 parts against one render of the same passes (the bound of merge.h).
#include "render/merge.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "backends/backend.h"
#include "seed_accumulation.h"
#include "test_paths.h"

namespace trazo {
namespace {

using test::MergeComparison;
using test::tempPath;

constexpr uint32_t kWidth = 4, kHeight = 3;

Fingerprint smallFingerprint() {
    Fingerprint f;
    f.scenePath = "a.scene";
    f.sceneHash = 1;
    f.width = kWidth;
    f.height = kHeight;
    f.blocks = "1,1,1,1";
    f.fullCycle = 4;
    f.version = "trazo test";
    return f;
}

// A part of passes `range` whose every sample is `value` (pixel i: value · (i + 1)).
std::string writePart(const std::string& name, PassRange range, double value, PassRange requested = {},
                      Fingerprint f = smallFingerprint()) {
    PartialHeader h;
    h.fingerprint = f;
    h.passes = {range};
    h.requested = requested.count() ? requested : range;
    h.rays = 1000 * range.count();
    h.seconds = 0.5 * range.count();
    h.backend = "cpu (test)";
    std::vector<AccumPixel> accum(kWidth * kHeight);
    for (size_t i = 0; i < accum.size(); ++i) {
        const double s = value * (double)(i + 1) * range.count();
        accum[i] = AccumPixel{{s, s, s}, (double)range.count(), {s / 2, s / 2, s / 2}, range.count() / 2.0};
    }
    const std::string path = tempPath(name);
    std::string error;
    EXPECT_TRUE(writePartialFile(path, h, accum, error)) << error;
    return path;
}

TEST(Merge, SumsContiguousPartsAndTheirCountsRaysAndSeconds) {
    const std::vector<std::string> parts{writePart("m0.part", {0, 4}, 1.0), writePart("m1.part", {4, 12}, 2.0)};
    MergeResult r;
    std::string error;
    ASSERT_TRUE(mergePartialFiles(parts, {}, r, error)) << error;
    EXPECT_EQ(r.header.passes, (std::vector<PassRange>{{0, 12}}));
    EXPECT_EQ(r.header.requested, (PassRange{0, 12}));
    EXPECT_TRUE(r.missing.empty());
    EXPECT_EQ(r.header.parts, 2u);
    EXPECT_EQ(r.header.rays, 12000u);
    EXPECT_EQ(r.header.seconds, 6.0);
    EXPECT_EQ(r.header.backend, "cpu (test)");
    ASSERT_EQ(r.accum.size(), (size_t)kWidth * kHeight);
    EXPECT_EQ(r.accum[2].count, 12.0);
    EXPECT_EQ(r.accum[2].sum[0], 3 * (1.0 * 4 + 2.0 * 8));  // exact in doubles
    EXPECT_EQ(r.accum[2].countB, 6.0);
}

TEST(Merge, RefusesPartsOfDifferentRendersNamingFilesAndField) {
    Fingerprint other = smallFingerprint();
    other.seed = 3;
    const std::string a = writePart("fa.part", {0, 4}, 1.0), b = writePart("fb.part", {4, 8}, 1.0, {}, other);
    MergeResult r;
    std::string error;
    EXPECT_FALSE(mergePartialFiles({b, a}, {}, r, error));
    EXPECT_EQ(error, b + ": cannot be merged with " + a + ": they differ in seed (0 vs 3)");
}

TEST(Merge, ReportsOverlappingPassesByNumber) {
    const std::string a = writePart("oa.part", {0, 8}, 1.0), b = writePart("ob.part", {6, 16}, 1.0);
    MergeResult r;
    std::string error;
    EXPECT_FALSE(mergePartialFiles({a, b}, {}, r, error));
    EXPECT_EQ(error, "passes 6:8 are in both " + a + " (0:8) and " + b + " (6:16)");
    MergeOptions gaps;
    gaps.allowGaps = true;  // never merges a pass twice
    EXPECT_FALSE(mergePartialFiles({a, b}, gaps, r, error));
}

TEST(Merge, ReportsMissingPassesByNumberAndAllowGapsMergesWhatExists) {
    // 8:16 missing between parts; 20:24 asked of the last part, which stopped at 20 (a time limit).
    const std::vector<std::string> parts{writePart("g0.part", {0, 8}, 1.0), writePart("g2.part", {16, 20}, 1.0, {16, 24})};
    MergeResult r;
    std::string error;
    EXPECT_FALSE(mergePartialFiles(parts, {}, r, error));
    EXPECT_EQ(error, "passes 8:16 are missing\npasses 20:24 are missing");
    // Parts that do not start at 0.
    EXPECT_FALSE(mergePartialFiles({parts[1]}, {}, r, error));
    EXPECT_EQ(error, "passes 0:16 are missing\npasses 20:24 are missing");

    MergeOptions gaps;
    gaps.allowGaps = true;
    ASSERT_TRUE(mergePartialFiles(parts, gaps, r, error)) << error;
    EXPECT_EQ(formatRanges(r.missing), "8:16,20:24");
    EXPECT_EQ(formatRanges(r.header.passes), "0:8,16:20");
    EXPECT_EQ(r.accum[0].count, 12.0);  // the passes there are
    EXPECT_EQ(r.accum[0].sum[0], 12.0);

    // The passes a merge must cover can be given: a whole missing last part is then named too.
    MergeOptions expected;
    expected.expected = PassRange{0, 32};
    EXPECT_FALSE(mergePartialFiles({parts[0], writePart("g1.part", {8, 24}, 1.0)}, expected, r, error));
    EXPECT_EQ(error, "passes 24:32 are missing");
    expected.expected = PassRange{0, 4};
    EXPECT_FALSE(mergePartialFiles({parts[0]}, expected, r, error));
    EXPECT_EQ(error, "passes 4:8 lie outside the passes asked for (0:4)");
}

TEST(Merge, AnyOrderOfThePartsGivesTheSameFile) {
    // Sums whose order matters in doubles: 1 + 2^-53 + 2^-53 is 1 from the left and 1 + 2^-52 from the right.
    const std::vector<std::string> parts{writePart("o0.part", {0, 1}, 1.0), writePart("o1.part", {1, 2}, 0x1p-53),
                                         writePart("o2.part", {2, 3}, 0x1p-53)};
    const std::vector<std::vector<size_t>> orders{{0, 1, 2}, {2, 1, 0}, {1, 2, 0}, {2, 0, 1}};
    std::string first;
    for (const auto& order : orders) {
        std::vector<std::string> listed;
        for (size_t i : order) listed.push_back(parts[i]);
        MergeResult r;
        std::string error;
        ASSERT_TRUE(mergePartialFiles(listed, {}, r, error)) << error;
        EXPECT_EQ(r.accum[0].sum[0], 1.0);  // pass order, from the left: what one render adds
        const std::string out = tempPath("order.part");
        ASSERT_TRUE(writePartialFile(out, r.header, r.accum, error)) << error;
        const std::string bytes = test::readFileText(out);
        if (first.empty()) first = bytes;
        EXPECT_EQ(bytes, first) << "order " << order[0] << order[1] << order[2];
    }
}

TEST(Merge, MergedPartialsMergeAgain) {
    const std::vector<std::string> parts{writePart("h0.part", {0, 3}, 0.1), writePart("h1.part", {3, 4}, 0.3),
                                         writePart("h2.part", {4, 9}, 0.7), writePart("h3.part", {9, 10}, 1.1)};
    std::string error;
    std::vector<std::string> halves;
    for (size_t half = 0; half < 2; ++half) {
        MergeOptions options;  // the second half starts at pass 4: it is asked for alone
        if (half == 1) options.expected = PassRange{4, 10};
        MergeResult r;
        ASSERT_TRUE(mergePartialFiles({parts[2 * half], parts[2 * half + 1]}, options, r, error)) << error;
        halves.push_back(tempPath("half" + std::to_string(half) + ".part"));
        ASSERT_TRUE(writePartialFile(halves.back(), r.header, r.accum, error)) << error;
    }
    MergeResult flat, tree;
    ASSERT_TRUE(mergePartialFiles(parts, {}, flat, error)) << error;
    ASSERT_TRUE(mergePartialFiles({halves[1], halves[0]}, {}, tree, error)) << error;
    EXPECT_EQ(tree.header.parts, 4u);
    EXPECT_EQ(formatRanges(tree.header.passes), "0:10");
    EXPECT_EQ(tree.header.rays, flat.header.rays);
    for (size_t i = 0; i < flat.accum.size(); ++i) {
        EXPECT_EQ(tree.accum[i].count, 10.0);
        EXPECT_NEAR(tree.accum[i].sum[1], flat.accum[i].sum[1], mergeRelativeBound(10) * flat.accum[i].sum[1]);
    }
}

TEST(Merge, BrokenPartsAreErrorsNamingThem) {
    const std::string good = writePart("b0.part", {0, 4}, 1.0), bad = writePart("b1.part", {4, 8}, 1.0);
    std::string bytes = test::readFileText(bad);
    bytes[bytes.size() - 20] ^= 1;
    std::ofstream(bad, std::ios::binary) << bytes;
    MergeResult r;
    std::string error;
    EXPECT_FALSE(mergePartialFiles({good, bad}, {}, r, error));
    EXPECT_EQ(error.rfind(bad + ": corrupt: ", 0), 0u) << error;
    std::ofstream(bad, std::ios::binary) << bytes.substr(0, bytes.size() - 30);
    EXPECT_FALSE(mergePartialFiles({good, bad}, {}, r, error));
    EXPECT_EQ(error, bad + ": truncated: " + std::to_string(bytes.size() - 30) + " bytes of " +
                         std::to_string(bytes.size()));
}

// The claim of docs/PARTIAL_FORMAT.md: a seed scene rendered as 4 partial files and merged equals one render of
// the same passes, counts exactly, sums within mergeRelativeBound, floats within one ulp.
TEST(Merge, SeedSceneInFourPartsEqualsOneRenderWithinTheBound) {
    constexpr uint32_t kPasses = 40;
    const std::vector<PassRange> ranges{{0, 7}, {7, 20}, {20, 21}, {21, 40}};
    std::unique_ptr<Backend> backend = createCpuBackend(2);
    const std::vector<AccumPixel> whole =
        test::renderSeedAccumulation(*backend, "scene1_area.scene", 64, 48, {{0, kPasses}});
    std::vector<std::string> parts;
    Fingerprint f = smallFingerprint();
    f.width = 64, f.height = 48;
    for (const PassRange& range : ranges) {
        PartialHeader h;
        h.fingerprint = f;
        h.passes = {range};
        h.requested = range;
        parts.push_back(tempPath("seed" + std::to_string(range.first) + ".part"));
        std::string error;
        ASSERT_TRUE(writePartialFile(parts.back(), h,
                                     test::renderSeedAccumulation(*backend, "scene1_area.scene", 64, 48, {range}), error))
            << error;
    }
    MergeResult r;
    std::string error;
    ASSERT_TRUE(mergePartialFiles({parts[2], parts[0], parts[3], parts[1]}, {}, r, error)) << error;
    const test::MergeComparison c = test::expectWithinMergeBound(r.accum, whole, kPasses);
    RecordProperty("identical_pixels", std::to_string(c.identicalPixels) + " of " + std::to_string(c.pixels));
    RecordProperty("identical_floats", std::to_string(c.identicalFloats));
    std::printf("[ merge ] %zu of %zu pixels identical in every double, %zu in every float; largest relative "
                "difference of a sum %.3g (bound %.3g)\n",
                c.identicalPixels, c.pixels, c.identicalFloats, c.largestRelative, mergeRelativeBound(kPasses));
    // The image is not black: the comparison compared something.
    double total = 0;
    for (const AccumPixel& p : whole) total += p.sum[0];
    EXPECT_GT(total, 0.0);
}

// Float samples of pass v for pixel i, with exponents spread over [lowExponent, highExponent].
float syntheticSample(size_t pixel, uint32_t pass, int lowExponent, int highExponent) {
    uint64_t h = (pixel * 0x9E3779B97F4A7C15ull) ^ (pass * 0xC2B2AE3D27D4EB4Full);
    h ^= h >> 29, h *= 0xBF58476D1CE4E5B9ull, h ^= h >> 32;
    const float mantissa = 1.0f + (float)(h & 0xFFFFFF) / 16777216.0f;
    return std::ldexp(mantissa, lowExponent + (int)((h >> 24) % (uint64_t)(highExponent - lowExponent + 1)));
}

// One render's sums (pass order) against 4 parts' sums added: `wide` spreads the samples over 2^-30..2^10,
// where doubles round; otherwise over 2^-3..2^3, where every partial sum is exact (n · max/min < 2^29).
MergeComparison compareSynthetic(bool wide) {
    constexpr uint32_t kPasses = 1000;
    constexpr size_t kPixels = 512;
    const std::vector<PassRange> ranges{{0, 100}, {100, 350}, {350, 351}, {351, kPasses}};
    std::vector<AccumPixel> single(kPixels, AccumPixel{}), merged(kPixels, AccumPixel{});
    for (const PassRange& range : ranges) {
        std::vector<AccumPixel> part(kPixels, AccumPixel{});
        for (size_t i = 0; i < kPixels; ++i)
            for (uint32_t v = range.first; v < range.end; ++v) {
                const float x = syntheticSample(i, v, wide ? -30 : -3, wide ? 10 : 3);
                part[i].add(Vec3(x, 0.5f * x, x), v % 2 == 1, 1.0f);
                single[i].add(Vec3(x, 0.5f * x, x), v % 2 == 1, 1.0f);
            }
        addAccumulation(merged, part);
    }
    return test::expectWithinMergeBound(merged, single, kPasses);
}

TEST(Merge, SumsThatRoundStayWithinTheBound) {
    const test::MergeComparison c = compareSynthetic(true);
    EXPECT_LT(c.identicalPixels, c.pixels / 2) << "the case must round, or the bound is not exercised";
    EXPECT_GT(c.largestRelative, 0.0);
    std::printf("[ merge ] samples over 2^-30..2^10: %zu of %zu pixels identical, %zu identical floats; largest "
                "relative difference %.3g (bound %.3g)\n",
                c.identicalPixels, c.pixels, c.identicalFloats, c.largestRelative, mergeRelativeBound(1000));
}

TEST(Merge, SumsOfFloatsInANarrowRangeAreExactInAnyOrder) {
    const test::MergeComparison c = compareSynthetic(false);
    EXPECT_EQ(c.identicalPixels, c.pixels);
}

TEST(Merge, BoundIsTwiceGammaOfTheSampleCount) {
    EXPECT_EQ(mergeRelativeBound(1), 0.0);
    EXPECT_NEAR(mergeRelativeBound(40), 2 * 39 * 0x1p-53, 1e-28);
    EXPECT_LT(mergeRelativeBound(1u << 26) + 0x1p-52, 0x1p-25);  // merge.h's one-ulp condition
    EXPECT_GT(mergeRelativeBound(1u << 27), 0x1p-25);
}

}  // namespace
}  // namespace trazo
