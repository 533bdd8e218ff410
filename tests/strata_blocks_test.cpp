// Blocks of strata per pass (integrator/strata.h): every cycle visits every stratum once at any block size,
// and renders at block sizes 1, 2, 4 or a whole grid are the same estimator — checked against closed forms
// (an area light over a wall, the indirect furnace) and against each other where grids nest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "flatten/flatten.h"
#include "render/strata_plan.h"
#include "render_harness.h"
#include "scene/scene_reader.h"
#include "test_paths.h"

namespace trazo::test {
namespace {

TEST(StrataBlocks, BlockIsTheLargestDivisorAtMostTheTarget) {
    EXPECT_EQ(blockFor(100, 1), 1u);
    EXPECT_EQ(blockFor(100, 16), 10u);
    EXPECT_EQ(blockFor(100, 50), 50u);
    EXPECT_EQ(blockFor(100, 99), 50u);
    EXPECT_EQ(blockFor(100, kWholeGrid), 100u);
    EXPECT_EQ(blockFor(97, 96), 1u);  // a prime grid has no block between 1 and itself
    EXPECT_EQ(blockFor(18, 4), 3u);
    EXPECT_EQ(blockFor(1, 7), 1u);
}

// At any block size and from any cycle boundary, blockPasses consecutive passes evaluate every stratum
// exactly once, for every pixel and grid.
TEST(StrataBlocks, EveryCycleVisitsEveryStratumOnce) {
    for (uint32_t count : {1u, 2u, 7u, 12u, 25u, 100u}) {
        for (uint32_t target : {1u, 2u, 3u, 5u, 10u, kWholeGrid}) {
            const uint32_t passes = blockPasses(count, target);
            for (uint32_t pixel = 0; pixel < 40; ++pixel) {
                for (uint32_t cycle : {0u, 3u}) {
                  for (uint32_t rotation : {0u, 5u}) {
                    std::vector<int> seen(count, 0);
                    for (uint32_t pass = cycle * passes; pass < (cycle + 1) * passes; ++pass) {
                        const StrataKey key{7u, pixel, pass, 1u};
                        const StrataBlock b = key.block(kGridAreaLightBase, count, target, rotation);
                        ASSERT_EQ(b.size, blockFor(count, target));
                        for (uint32_t j = 0; j < b.size; ++j) {
                            const uint32_t s = b.stratum(j);
                            ASSERT_LT(s, count);
                            ++seen[s];
                        }
                    }
                    for (uint32_t s = 0; s < count; ++s)
                        ASSERT_EQ(seen[s], 1) << "count " << count << " target " << target << " stratum " << s;
                  }
                }
            }
        }
    }
}

// The points Q of one pass's indirect directions share a key; rotated by the direction's index, up to P of
// them take P different blocks of the light in the same pass.
TEST(StrataBlocks, RotatedDirectionsTakeDifferentBlocksInOnePass) {
    for (uint32_t pass = 0; pass < 30; ++pass) {
        const StrataKey key{2u, 9u, pass, 77u};
        std::vector<int> taken(25, 0);
        for (uint32_t direction = 0; direction < 18; ++direction) ++taken[key.block(kGridAreaLightBase, 25, 1, direction).offset];
        for (int t : taken) ASSERT_LE(t, 1);
    }
}

// A block of one is the plain progressive order: exactly the stratum stratumForPass gives.
TEST(StrataBlocks, BlocksOfOneAreThePassOrder) {
    for (uint32_t pass = 0; pass < 60; ++pass) {
        const StrataKey key{3u, 17u, pass, 5u};
        EXPECT_EQ(key.block(kGridIndirect, 18, 1).stratum(0),
                  stratumForPass(3u, 17u, hashCombine(5u, kGridIndirect), pass, 18));
    }
}

// A Lambertian wall under a 4×2 area light, nothing in between (every shading point faces the light).
std::string wallUnderAreaLight() {
    return "SceneSettings\n{\nRenderWidth 12\nRenderHeight 12\nReflectionQuality 0\nIndirectQuality 0\n}\n"
           "Camera\n{\nPOV 0 0 10\nPOI 0 0 0\nFOV 20\n}\n"
           "Material\n{\nName wall\nDiffuseColor 1 1 1\nSpecularColor 0 0 0\nRoughness 0\n}\n"
           "Box\n{\nMaterial wall\nScale 100 100 1\nTranslation 0 0 -0.5\n}\n"
           "AreaLight\n{\nPosition 0.3 -0.2 12\nDirection 0 0 -1\nWidth 2\nHeight 1\nSubdivision 4 2\nColor 1 1 1\n}\n";
}

TEST(StrataBlocks, FullCycleIsTheLcmOfTheBlockCounts) {
    Diagnostics diags;
    const std::string text = wallUnderAreaLight();
    const Scene scene = readSceneText(text, tempPath("blocks_cycle.scene"), diags);
    ASSERT_FALSE(diags.hasErrors());
    const SceneArrays arrays = flatten(scene).arrays;
    EXPECT_EQ(fullCyclePasses(arrays, StrataBlocks::ones()), 8u);
    EXPECT_EQ(fullCyclePasses(arrays, StrataBlocks{1, 2, 1, 1}), 4u);
    EXPECT_EQ(fullCyclePasses(arrays, StrataBlocks{1, 3, 1, 1}), 4u);  // 3 ∤ 8: blocks of 2
    EXPECT_EQ(fullCyclePasses(arrays, StrataBlocks::whole()), 1u);
}

// One cycle traces one camera ray per pass and each light cell once per shading point, at every block size.
TEST(StrataBlocks, OneCycleTracesEveryCellOnce) {
    for (uint32_t target : {1u, 2u, 4u, kWholeGrid}) {
        const uint32_t passes = blockPasses(8, target);
        const RenderedImage image =
            renderSceneText(wallUnderAreaLight(), {.passes = passes, .blocks = StrataBlocks{1, target, 1, 1}});
        ASSERT_FALSE(image.pixels.empty());
        EXPECT_EQ(image.rays, uint64_t(12 * 12) * (passes + 8)) << "target " << target;
    }
}

// Exact pixel values of wallUnderAreaLight(): the mean of cos θ over the rectangle (σ = 0, Kd = 1, no
// falloff), by a fine midpoint rule in double precision, independently of the renderer.
std::vector<double> wallClosedForm() {
    std::vector<double> exact;
    const double t = std::tan(10.0 * M_PI / 180.0);
    for (int j = 0; j < 12; ++j)
        for (int i = 0; i < 12; ++i) {
            const double dx = (2.0 * (i + 0.5) / 12 - 1.0) * t, dy = (1.0 - 2.0 * (j + 0.5) / 12) * t;
            const double px = 10 * dx, py = 10 * dy;  // the wall at z = 0, camera at z = 10
            double sum = 0;
            const int m = 400;
            for (int a = 0; a < m; ++a)
                for (int b = 0; b < m; ++b) {
                    const double lx = 0.3 - 1 + 2 * (a + 0.5) / m - px, ly = -0.2 - 0.5 + (b + 0.5) / m - py, lz = 12;
                    sum += lz / std::sqrt(lx * lx + ly * ly + lz * lz);
                }
            exact.push_back(sum / (m * m));
        }
    return exact;
}

// z of the mean of x: |z| < 4 fails a correct renderer with probability 6e-5, and catches a bias of 5
// standard errors with probability 0.84.
double zScore(const std::vector<double>& x) {
    double mean = 0, sq = 0;
    for (double v : x) mean += v;
    mean /= double(x.size());
    for (double v : x) sq += (v - mean) * (v - mean);
    const double se = std::sqrt(sq / double(x.size() - 1) / double(x.size()));
    return mean / se;
}

// The errors from exact[i] at each pixel i of `scene` rendered for `passes` in `blocks`, seeds 1 .. seeds.
std::vector<double> pixelErrors(const std::string& scene, uint32_t passes, const StrataBlocks& blocks, uint32_t seeds,
                                const std::vector<double>& exact) {
    std::vector<double> errors;
    for (uint32_t seed = 1; seed <= seeds; ++seed) {
        const RenderedImage image = renderSceneText(scene, {.passes = passes, .seed = seed, .blocks = blocks});
        EXPECT_EQ(image.pixels.size(), exact.size());
        for (size_t i = 0; i < std::min(image.pixels.size(), exact.size()); ++i)
            errors.push_back(image.pixels[i].x - exact[i]);
    }
    return errors;
}

// One cycle at block sizes 1, 2, 4 and the whole light are unbiased estimates of the exact image: over 144
// pixels × 12 seeds, the mean error is within 4 standard errors of 0. The standard error is ~1e-4 of the
// pixel value, so a block that skipped or doubled one of the 8 cells (a 1/8 bias) would fail by far.
TEST(StrataBlocks, EveryBlockSizeMatchesTheClosedForm) {
    const std::vector<double> exact = wallClosedForm();
    for (uint32_t target : {1u, 2u, 4u, kWholeGrid}) {
        const std::vector<double> errors =
            pixelErrors(wallUnderAreaLight(), blockPasses(8, target), StrataBlocks{1, target, 1, 1}, 12, exact);
        EXPECT_LT(std::abs(zScore(errors)), 4.0) << "target " << target;
    }
}

// The furnace of indirect_test.cpp (uniform emitter, no lights): Indirect = ColorBleeding · Kd · E · 2/π.
// One cycle of the 18 directions (q = 3) in blocks of 1, 2, 6 and 18 is unbiased.
TEST(StrataBlocks, IndirectBlocksMatchTheClosedForm) {
    const std::string scene =
        settingsText(12, 8, 0, 3, "ColorBleeding 1\n") + cameraText("0 0 10", "0 0 0", "30") +
        "Material\n{\nName wall\nDiffuseColor 0.5 0.5 0.5\nSpecularColor 0 0 0\nRoughness 0\n}\n" +
        blackMaterialText("sky", "EmissiveColor 1 1 1\n") +
        "Box\n{\nMaterial wall\nTranslation 0 0 -0.5\nScale 100 100 1\n}\n"
        "Sphere\n{\nMaterial sky\nCenter 0 0 0\nRadius 500\n}\n";
    const std::vector<double> exact(12 * 8, 0.5 * 2.0 / M_PI);
    for (uint32_t target : {1u, 2u, 6u, kWholeGrid}) {
        const std::vector<double> errors =
            pixelErrors(scene, blockPasses(18, target), StrataBlocks{1, 1, target, 1}, 6, exact);
        EXPECT_LT(std::abs(zScore(errors)), 4.0) << "target " << target;
    }
}

// Where grids nest (indirect directions × light cells at Q, with a shadowing wall), block sizes change
// the pairing but not the expectation: per pixel, the difference of two block settings' means over seeds
// is centred on 0.
TEST(StrataBlocks, NestedGridsAgreeAcrossBlockSizes) {
    const std::string scene =
        settingsText(10, 10, 0, 2, "ColorBleeding 4\n") + cameraText("0 1 4", "0 0 0", "50") +
        "Material\n{\nName m\nDiffuseColor 0.8 0.8 0.8\nSpecularColor 0 0 0\nRoughness 0.5\n}\n"
        "Box\n{\nMaterial m\nTranslation 0 -0.5 0\nScale 6 1 6\n}\n"
        "Box\n{\nMaterial m\nTranslation 0 0.5 -1.5\nScale 3 2 0.2\n}\n"
        "AreaLight\n{\nPosition 0 1.2 0.5\nDirection 0 -1 0\nWidth 3\nHeight 3\nSubdivision 2 2\nColor 1 1 1\n}\n";
    auto meanOverSeeds = [&](const StrataBlocks& blocks, uint32_t firstSeed) {
        Diagnostics diags;
        const Scene s = readSceneText(scene, tempPath("nested.scene"), diags);
        const uint32_t cycle = fullCyclePasses(flatten(s).arrays, blocks);
        std::vector<double> sum;
        for (uint32_t seed = firstSeed; seed < firstSeed + 8; ++seed) {
            const RenderedImage image = renderSceneText(scene, {.passes = 2 * cycle, .seed = seed, .blocks = blocks});
            sum.resize(image.pixels.size(), 0.0);
            for (size_t i = 0; i < sum.size(); ++i) sum[i] += image.pixels[i].x / 8;
        }
        return sum;
    };
    const std::vector<double> base = meanOverSeeds(StrataBlocks::ones(), 1);
    for (const StrataBlocks& blocks : {StrataBlocks{1, 2, 2, 2}, StrataBlocks{1, kWholeGrid, kWholeGrid, 1},
                                       StrataBlocks::whole()}) {
        const std::vector<double> other = meanOverSeeds(blocks, 101);
        std::vector<double> differences;
        for (size_t i = 0; i < base.size(); ++i) differences.push_back(other[i] - base[i]);
        EXPECT_LT(std::abs(zScore(differences)), 4.0) << describeBlocks(blocks);
    }
}

// Same seed and blocks ⇒ the same image whatever the thread count.
TEST(StrataBlocks, DeterministicAcrossThreadCounts) {
    for (const StrataBlocks& blocks : {StrataBlocks{1, 2, 1, 1}, StrataBlocks::whole()}) {
        const RenderedImage one = renderSceneText(wallUnderAreaLight(), {.passes = 5, .threads = 1, .seed = 4, .blocks = blocks});
        const RenderedImage three = renderSceneText(wallUnderAreaLight(), {.passes = 5, .threads = 3, .seed = 4, .blocks = blocks});
        ASSERT_EQ(one.pixels.size(), three.pixels.size());
        for (size_t i = 0; i < one.pixels.size(); ++i) ASSERT_EQ(one.pixels[i].x, three.pixels[i].x) << i;
    }
}

// The headless rule on seed scenes: whole camera-path grids (scene 1: one pass), blocks that complete in the
// glossy cones' 2q² passes (scene 6: 100 cells in 50 passes), one rotated light cell per indirect direction
// (scene 9: the 18 directions whole, the 25 cells at Q over a 25-pass full cycle).
TEST(StrataBlocks, HeadlessRuleOnSeedScenes) {
    struct Expected {
        const char* scene;
        const char* blocks;
        uint32_t cameraPath, full;
    };
    for (const Expected& e : {Expected{"scenes/scene1_area.scene", "1,100,1,1", 1, 1},
                              Expected{"scenes/scene6_glossy.scene", "1,2,1,1", 50, 50},
                              Expected{"scenes/scene9_indirect.scene", "1,25,18,1", 1, 25}}) {
        Diagnostics diags;
        const Scene scene = readSceneFile(sourcePath(e.scene), diags);
        ASSERT_FALSE(diags.hasErrors()) << e.scene;
        const SceneArrays arrays = flatten(scene).arrays;
        const StrataBlocks blocks = headlessBlocks(arrays);
        EXPECT_EQ(describeBlocks(blocks), e.blocks) << e.scene;
        EXPECT_EQ(cameraPathPasses(arrays, blocks), e.cameraPath) << e.scene;
        EXPECT_EQ(fullCyclePasses(arrays, blocks), e.full) << e.scene;
    }
}

TEST(StrataBlocks, ParsesTheCommandLineForms) {
    StrataBlocks b;
    std::string why;
    ASSERT_TRUE(parseStrataBlocks("whole", b, why));
    EXPECT_EQ(b, StrataBlocks::whole());
    ASSERT_TRUE(parseStrataBlocks("1,100,whole,5", b, why));
    EXPECT_EQ(b, (StrataBlocks{1, 100, kWholeGrid, 5}));
    EXPECT_EQ(describeBlocks(b), "1,100,whole,5");
    for (const char* bad : {"", "0", "1,2", "1,2,3,4,5", "x", "1,,2,3", "-1", "4294967296"})
        EXPECT_FALSE(parseStrataBlocks(bad, b, why)) << bad;
}

}  // namespace
}  // namespace trazo::test
