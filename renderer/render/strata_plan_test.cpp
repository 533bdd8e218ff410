// The bounds that keep a render's strata inside 32-bit arithmetic, the kernels' guards against a wrapped grid
// and blockFor's bounded search (render/strata_plan.h, integrator/strata.h).
#include "render/strata_plan.h"

#include <gtest/gtest.h>

#include <chrono>

namespace trazo {
namespace {

uint32_t blockForByHand(uint32_t count, uint32_t target) {
    uint32_t best = 1;
    for (uint32_t b = 1; b <= count && b <= target; ++b)
        if (count % b == 0) best = b;
    return best;
}

TEST(BlockFor, IsTheLargestDivisorAtMostTheTarget) {
    for (uint32_t count = 1; count <= 300; ++count)
        for (uint32_t target = 1; target <= count + 2; ++target)
            ASSERT_EQ(blockFor(count, target), blockForByHand(count, target)) << count << " " << target;
    // Large grids, prime and composite, with targets on both sides of √count.
    for (uint32_t count : {1048573u, 1048576u, 2u * 524287u, 999983u * 3u, 1024u * 1023u})
        for (uint32_t target : {2u, 3u, 1000u, 1023u, 1025u, 4096u, 524286u, 524288u, 1048000u, count - 1u})
            ASSERT_EQ(blockFor(count, target), blockForByHand(count, target)) << count << " " << target;
    EXPECT_EQ(blockFor(0, 5), 1u);  // a wrapped grid: one stratum, no division by zero
    EXPECT_EQ(blockFor(0, kWholeGrid), 1u);
}

// A target just below a prime grid of 2^32 − 5 cells searched down 4·10⁹ steps; now about 2·√count at most.
TEST(BlockFor, SearchIsBoundedNearAHugePrime) {
    const auto t0 = std::chrono::steady_clock::now();
    uint32_t sum = 0;
    for (uint32_t i = 0; i < 20; ++i) sum += blockFor(4294967291u, 4294967290u - i) + blockFor(4294967291u, 70000u + i);
    EXPECT_EQ(sum, 40u);  // a prime: only blocks of 1 tile it
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 2.0);
}

TEST(StrataGuards, AWrappedGridOfZeroStrataDividesNothingByZero) {
    EXPECT_EQ(permuteIndex(7, 0, 123), 0u);
    EXPECT_EQ(permuteIndex(7, 1, 123), 0u);
    EXPECT_EQ(stratumForPass(1, 2, 3, 4, 0), 0u);
    const StrataKey key{1, 2, 3, 4};
    for (uint32_t target : {1u, 7u, kWholeGrid}) {
        const StrataBlock b = key.block(kGridIndirect, 0u, target, 5u);
        EXPECT_EQ(b.blocks, 1u);
        EXPECT_EQ(b.size, 1u);
        EXPECT_EQ(b.stratum(0), 0u);
    }
    EXPECT_EQ(blockPasses(0, 1), 0u);  // no cycle to wait for
    // 65536 × 65536 and 2·65536² wrap to 0 in 32 bits: what a kernel would see without the read-time bounds.
    EXPECT_EQ(uint32_t(65536u * 65536u), 0u);
    EXPECT_EQ(key.stratum(kGridGlossy, uint32_t(2u * 65536u * 65536u)), 0u);
}

Scene sceneWith(int reflectionQuality, int indirectQuality, int reflectionSteps, int nx, int ny) {
    Scene s;
    s.path = "t.scene";
    s.settings.reflectionQuality = reflectionQuality;
    s.settings.indirectQuality = indirectQuality;
    s.settings.reflectionSteps = reflectionSteps;
    s.settings.indirectQualityAt = SourceLocation{"t.scene", 7, 5};
    AreaLight l;
    l.subdivisionX = nx;
    l.subdivisionY = ny;
    l.where = SourceLocation{"t.scene", 20, 1};
    s.areaLights.push_back(l);
    return s;
}

TEST(RenderBounds, AcceptUpToTheLimitsAndRefuseBeyondWithTheLine) {
    Diagnostics ok;
    EXPECT_TRUE(checkRenderBounds(sceneWith(724, 724, 65536, 1024, 1024), ok));
    EXPECT_TRUE(ok.items.empty());

    Diagnostics d;
    EXPECT_FALSE(checkRenderBounds(sceneWith(725, 65536, 65537, 65536, 65536), d));
    ASSERT_EQ(d.items.size(), 4u);
    std::string all;
    for (const Diagnostic& x : d.items) all += formatDiagnostic(x) + "\n";
    EXPECT_NE(all.find("ReflectionQuality 725"), std::string::npos) << all;
    EXPECT_NE(all.find("t.scene:7:5: error: IndirectQuality 65536 asks for 2·q² = 8589934592 strata"),
              std::string::npos) << all;
    EXPECT_NE(all.find("ReflectionSteps 65537"), std::string::npos) << all;
    EXPECT_NE(all.find("t.scene:20:1: error: Subdivision 65536 65536 asks for 4294967296 cells"), std::string::npos)
        << all;
    EXPECT_FALSE(checkRenderBounds(sceneWith(3, 3, 1, 1048577, 1), d));  // a product, not each side
}

}  // namespace
}  // namespace trazo
