// The error probe: its draw, its estimate against a known variance, and the backend rendering exactly the
// drawn pixels with the probe's seed.
#include "render/error_probe.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/rng.h"
#include "flatten/flatten.h"
#include "render/frame_setup.h"
#include "render/progressive_render.h"
#include "scene/scene_reader.h"
#include "test_scenes.h"

namespace trazo {
namespace {

// An image of value v(x) per pixel after its first pass, n samples.
std::vector<AccumPixel> flatImage(uint32_t width, uint32_t height, double passes, double (*value)(uint32_t, uint32_t)) {
    std::vector<AccumPixel> image((size_t)width * height);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            AccumPixel& p = image[(size_t)y * width + x];
            p.count = passes;
            for (int c = 0; c < 3; ++c) p.sum[c] = passes * value(x, y);
        }
    return image;
}

TEST(ErrorProbe, DrawsAboutTheBaseShareAndEveryBrightPixel) {
    // 512²: a dim image with 20 pixels 100 times brighter (a highlight).
    auto value = [](uint32_t x, uint32_t y) { return (y == 200 && x >= 100 && x < 120) ? 20.0 : 0.2; };
    const std::vector<AccumPixel> image = flatImage(512, 512, 1.0, value);
    for (uint32_t seed : {0u, 1u, 77u}) {
        const ErrorProbe probe = designProbe(image, 512, 512, seed);
        ASSERT_EQ(probe.pixels.size(), probe.weights.size());
        // π = min(1, 1/64 + s·τ⁻¹), s = Σ_c value², τ⁻¹ = 0.25·4096 / Σ s: the 20 bright pixels (s = 1200) are
        // capped at 1, each dim one (s = 0.12) has 1/64 + 0.12·τ⁻¹. Poisson count: ±4σ ≈ ±275.
        const double perValue = 0.25 * 4096.0 / (262124.0 * 0.12 + 20.0 * 1200.0);
        const double dimChance = 1.0 / 64.0 + 0.12 * perValue;
        EXPECT_NEAR((double)probe.pixels.size(), 262124.0 * dimChance + 20.0, 275.0) << seed;
        EXPECT_TRUE(std::is_sorted(probe.pixels.begin(), probe.pixels.end()));
        int bright = 0;
        for (size_t k = 0; k < probe.pixels.size(); ++k) {
            const uint32_t x = probe.pixels[k] % 512, y = probe.pixels[k] / 512;
            if (value(x, y) > 1.0) {
                ++bright;
                EXPECT_EQ(probe.weights[k], 1.0);  // drawn with certainty
            } else {
                EXPECT_NEAR(probe.weights[k], 1.0 / dimChance, 1e-9);
            }
        }
        EXPECT_EQ(bright, 20) << seed;
    }
    // Tiny images: every pixel.
    const std::vector<AccumPixel> tiny = flatImage(5, 3, 1.0, [](uint32_t, uint32_t) { return 0.5; });
    EXPECT_EQ(designProbe(tiny, 5, 3, 4).pixels.size(), 15u);
    EXPECT_TRUE(designProbe({}, 0, 0, 4).empty());
    EXPECT_NE(probeFrame(FrameParams{}).seed, FrameParams{}.seed);
    EXPECT_TRUE(probeFrame(FrameParams{}).target.probe);
}

// The draw as the header states it, in two plain passes: the total first, then each pixel's chance.
ErrorProbe probeByTheFormula(const std::vector<AccumPixel>& image, uint32_t seed) {
    auto squared = [](const AccumPixel& p) {
        double s = 0.0;
        if (p.count > 0.0)
            for (int c = 0; c < 3; ++c) s += (p.sum[c] / p.count) * (p.sum[c] / p.count);
        return s;
    };
    const size_t n = image.size();
    const double base = std::max(std::min(kProbeMaxBaseShare, double(kProbeBasePixels) / double(n)),
                                 std::min(1.0, double(kProbeMinPixels) / double(n)));
    double total = 0.0;
    for (const AccumPixel& p : image) total += squared(p);
    const double perValue = total > 0.0 ? kProbeBrightShare * base * double(n) / total : 0.0;
    const uint32_t key = hashCombine(seed, 0x70726f62u + 1u);
    ErrorProbe probe;
    for (size_t i = 0; i < n; ++i) {
        const double chance = std::min(1.0, base + perValue * squared(image[i]));
        if (double(hashCombine(key, (uint32_t)i)) * 0x1p-32 < chance) {
            probe.pixels.push_back((uint32_t)i);
            probe.weights.push_back(1.0 / chance);
        }
    }
    return probe;
}

// growProbe, as its comment states it: pixel i is probed when u_i < the larger of its chances under the two
// images, with weight 1/that; the pixels added are those the first draw lacked. Images: random, the second
// with new bright pixels (a glossy highlight's rare sample after the first pass) and others dimmed.
TEST(ErrorProbe, GrowsToTheLargestChanceEachPixelHad) {
    std::mt19937 rng(7);
    std::exponential_distribution<double> bright(1.0);
    const uint32_t width = 300, height = 200;
    std::vector<AccumPixel> first((size_t)width * height), now(first.size());
    for (size_t i = 0; i < first.size(); ++i) {
        const double v = bright(rng), w = i % 997 == 3 ? 400.0 : (i % 5 == 0 ? 0.2 * v : v);
        first[i].count = 1.0;
        now[i].count = 6.0;
        for (int c = 0; c < 3; ++c) first[i].sum[c] = v * (1.0 + 0.1 * c), now[i].sum[c] = 6.0 * w * (1.0 + 0.1 * c);
    }
    for (uint32_t seed : {2u, 13u}) {
        // Each image's draw by the formula. A pixel in one draw only has its chance under the other below u_i,
        // so the larger chance is the one its own draw weighs it by.
        const ErrorProbe before = probeByTheFormula(first, seed), after = probeByTheFormula(now, seed);
        ErrorProbe probe = designProbe(first, width, height, seed);
        ASSERT_EQ(probe.pixels, before.pixels);
        const ErrorProbe added = growProbe(now, width, height, seed, probe);
        // Expected: the union of both draws, weighted by the larger chance (the smaller weight).
        std::vector<double> weightOf(first.size(), 0.0);
        for (size_t k = 0; k < before.pixels.size(); ++k) weightOf[before.pixels[k]] = before.weights[k];
        std::vector<uint32_t> expectedAdded;
        for (size_t k = 0; k < after.pixels.size(); ++k) {
            const uint32_t i = after.pixels[k];
            if (weightOf[i] == 0.0) expectedAdded.push_back(i);
            weightOf[i] = weightOf[i] == 0.0 ? after.weights[k] : std::min(weightOf[i], after.weights[k]);
        }
        // A pixel drawn first keeps its place even where the new image would not draw it; its weight may only
        // fall (its chance only rise).
        EXPECT_EQ(added.pixels, expectedAdded) << seed;
        EXPECT_FALSE(added.pixels.empty());
        for (size_t k = 0; k < probe.pixels.size(); ++k) EXPECT_EQ(probe.weights[k], weightOf[probe.pixels[k]]);
        for (size_t k = 0; k < added.pixels.size(); ++k) EXPECT_EQ(added.weights[k], weightOf[added.pixels[k]]);
        for (size_t i = 3; i < now.size(); i += 997)  // every new bright pixel is probed
            EXPECT_TRUE(std::binary_search(probe.pixels.begin(), probe.pixels.end(), (uint32_t)i) ||
                        std::binary_search(added.pixels.begin(), added.pixels.end(), (uint32_t)i))
                << i;

        // Merged: ascending, each pixel's accumulation beside it.
        std::vector<AccumPixel> probeAccum(probe.pixels.size()), addedAccum(added.pixels.size());
        for (size_t k = 0; k < probe.pixels.size(); ++k) probeAccum[k].sum[0] = probe.pixels[k];
        for (size_t k = 0; k < added.pixels.size(); ++k) addedAccum[k].sum[0] = added.pixels[k];
        const size_t total = probe.pixels.size() + added.pixels.size();
        addToProbe(probe, probeAccum, added, addedAccum);
        ASSERT_EQ(probe.pixels.size(), total);
        ASSERT_EQ(probe.weights.size(), total);
        ASSERT_EQ(probeAccum.size(), total);
        EXPECT_TRUE(std::is_sorted(probe.pixels.begin(), probe.pixels.end()));
        for (size_t k = 0; k < total; ++k) {
            EXPECT_EQ(probeAccum[k].sum[0], probe.pixels[k]);
            EXPECT_EQ(probe.weights[k], weightOf[probe.pixels[k]]);
        }
        // Grown again from the same image: nothing more.
        EXPECT_TRUE(growProbe(now, width, height, seed, probe).empty());
    }
}

// The grown probe stays unbiased where the error is a rare bright sample: per pixel and pass, a sample is
// 1 + 200 with chance 1/400, else 1 (variance 200² · (1/400)(399/400) per pass); passes 2–8 can land bright
// samples the first pass's draw knew nothing of. Over many renders the mean estimated MSE must match the true
// one: tested against 4 standard errors of the renders' own spread (a false failure ~1 in 16 000 were the
// mean normal; it is a mean of 400 renders).
TEST(ErrorProbe, GrownProbeIsUnbiasedForRareBrightSamples) {
    const uint32_t width = 64, height = 64, passes = 8;
    const double spike = 200.0, chance = 1.0 / 400.0;
    std::mt19937 rng(21);
    std::bernoulli_distribution rare(chance);
    auto render = [&](AccumPixel& p, uint32_t from, uint32_t to) {
        for (uint32_t pass = from; pass < to; ++pass) {
            const double v = 1.0 + (rare(rng) ? spike : 0.0);
            p.count += 1.0;
            for (int c = 0; c < 3; ++c) p.sum[c] += v;
        }
    };
    const double mse = spike * spike * chance * (1.0 - chance) / passes;  // per channel and pixel
    constexpr int kRenders = 400;
    double sum = 0.0, squares = 0.0;
    for (int r = 0; r < kRenders; ++r) {
        std::vector<AccumPixel> image((size_t)width * height);
        for (AccumPixel& p : image) render(p, 0, 1);
        ErrorProbe probe = designProbe(image, width, height, (uint32_t)r);
        for (AccumPixel& p : image) render(p, 1, passes);
        std::vector<AccumPixel> probeAccum(probe.pixels.size());
        for (AccumPixel& p : probeAccum) render(p, 0, passes);
        const ErrorProbe added = growProbe(image, width, height, (uint32_t)r, probe);
        std::vector<AccumPixel> addedAccum(added.pixels.size());
        for (AccumPixel& p : addedAccum) render(p, 0, passes);
        addToProbe(probe, probeAccum, added, addedAccum);
        const ErrorEstimate e = estimateErrorWithProbe(image, probe, probeAccum);
        ASSERT_TRUE(e.available);
        sum += e.rmse * e.rmse;
        squares += e.rmse * e.rmse * e.rmse * e.rmse;
    }
    const double mean = sum / kRenders, spread = std::sqrt(std::max(0.0, squares / kRenders - mean * mean));
    EXPECT_NEAR(mean, mse, 4.0 * spread / std::sqrt(double(kRenders))) << "true MSE " << mse;
}

// designProbe's one pass over the image (with its candidates) draws exactly the formula's pixels and weights:
// images dark at the top (a small running total for long), bright at the top, a single bright pixel, all black,
// random, after one pass and after several.
TEST(ErrorProbe, DrawIsTheFormulasBitForBit) {
    std::mt19937 rng(5);
    std::exponential_distribution<double> bright(1.0);
    for (int kind = 0; kind < 5; ++kind) {
        for (double passes : {1.0, 3.0}) {
            const uint32_t width = 300, height = 200;
            std::vector<AccumPixel> image((size_t)width * height);
            for (size_t i = 0; i < image.size(); ++i) {
                const uint32_t y = uint32_t(i / width);
                double v = 0.0;
                switch (kind) {
                    case 0: v = y < 150 ? 0.0 : bright(rng); break;    // black on top
                    case 1: v = y < 20 ? 50.0 : 0.1 * bright(rng); break;  // a bright band on top
                    case 2: v = i == 40000 ? 1e3 : 0.0; break;         // one bright pixel
                    case 3: v = 0.0; break;
                    default: v = bright(rng) * bright(rng); break;
                }
                image[i].count = passes;
                for (int c = 0; c < 3; ++c) image[i].sum[c] = passes * v * (1.0 + 0.1 * c);
            }
            for (uint32_t seed : {1u, 9u}) {
                const ErrorProbe expected = probeByTheFormula(image, seed);
                const ErrorProbe got = designProbe(image, width, height, seed);
                ASSERT_EQ(got.pixels, expected.pixels) << "kind " << kind << " passes " << passes << " seed " << seed;
                ASSERT_EQ(got.weights, expected.weights) << "kind " << kind;
            }
        }
    }
}

// Image and probe pixels drawn independently from N(mu, sigma²) per channel: the estimate recovers sigma.
TEST(ErrorProbe, EstimateRecoversAKnownVariance) {
    const uint32_t width = 256, height = 256;
    std::mt19937 rng(11);
    std::normal_distribution<double> noise(0.0, 0.05);
    auto sample = [&](AccumPixel& p, double mu, double passes) {
        p.count = passes;
        for (int c = 0; c < 3; ++c) p.sum[c] = passes * (mu + noise(rng));
    };
    auto mu = [&](uint32_t i) { return 0.1 + 0.8 * (i % width) / width; };
    std::vector<AccumPixel> image((size_t)width * height);
    for (uint32_t i = 0; i < width * height; ++i) sample(image[i], mu(i), 4.0);
    const ErrorProbe probe = designProbe(image, width, height, 3);
    std::vector<AccumPixel> probeAccum(probe.pixels.size());
    for (size_t k = 0; k < probe.pixels.size(); ++k) sample(probeAccum[k], mu(probe.pixels[k]), 4.0);
    const ErrorEstimate e = estimateErrorWithProbe(image, probe, probeAccum);
    ASSERT_TRUE(e.available);
    EXPECT_EQ(e.probePixels, probe.pixels.size());
    // ~5000 pixels, 3 channels of σ²χ²₁ weighted by 1/π within a factor ~2: the MSE estimate's relative
    // deviation is ~2 %, so 10 % on the RMSE (20 % on the MSE) is a many-σ bound.
    EXPECT_NEAR(e.rmse, 0.05, 0.005);
    EXPECT_NEAR(e.meanValue, 0.5, 0.01);
    EXPECT_NEAR(e.relError, 0.1, 0.01);

    // A probe that did not render the image's passes gives no estimate.
    probeAccum[5].count = 3.0;
    EXPECT_FALSE(estimateErrorWithProbe(image, probe, probeAccum).available);
    EXPECT_FALSE(estimateErrorWithProbe(image, probe, {}).available);
}

const std::string kAreaLightScene =
    test::penumbraSceneText("    RenderWidth 37\n    RenderHeight 23\n    IndirectQuality 0\n    Antialiasing 4\n");

// The probe's pixel k is bit for bit image pixel pixels[k] of a render with the probe's seed: the backend maps
// the right pixels and the probe is the image's own estimator.
class ErrorProbeOn : public ::testing::TestWithParam<BackendChoice> {};

TEST_P(ErrorProbeOn, BackendRendersTheDrawnPixelsWithTheProbeSeed) {
    const BackendChoice choice = GetParam();
    std::string device;
    if (choice == BackendChoice::Cuda && !cudaDeviceAvailable(device))
        GTEST_SKIP() << "no CUDA device (" << (device.empty() ? "this build has no CUDA backend" : device)
                     << "): the CUDA probe's pixels are not checked";
    Diagnostics diags;
    const Scene scene = readSceneText(kAreaLightScene, "probe.scene", diags);
    ASSERT_FALSE(diags.hasErrors());
    const SceneArrays arrays = flatten(scene).arrays;
    std::string error;
    {
        auto backend = createBackend(choice, 2, error);
        ASSERT_TRUE(backend) << error;
        ASSERT_TRUE(backend->hasProbe());
        backend->upload(arrays);
        const uint32_t w = 37, h = 23;
        backend->resize(w, h);
        const FrameParams frame = makeFrameParams(scene, w, h, 9);
        RenderLimits limits;
        limits.passes = 3;
        limits.cyclePasses = fullCyclePasses(arrays, StrataBlocks::ones());
        limits.errorProbe = true;
        const RenderOutcome outcome = renderProgressive(*backend, frame, limits);
        ASSERT_FALSE(outcome.probe.empty());
        std::vector<AccumPixel> probe;
        backend->readProbe(probe);

        // The same passes as an image, with the probe's seed.
        backend->reset();
        FrameParams asImage = probeFrame(frame);
        asImage.target = PassPixels{};
        RenderLimits plain = limits;
        plain.errorProbe = false;
        renderProgressive(*backend, asImage, plain);
        std::vector<AccumPixel> image;
        backend->readAccumulation(image);
        ASSERT_EQ(probe.size(), outcome.probe.pixels.size());
        for (size_t k = 0; k < probe.size(); ++k) {
            const AccumPixel& q = image[outcome.probe.pixels[k]];
            ASSERT_EQ(probe[k].count, 3.0);
            for (int c = 0; c < 3; ++c) ASSERT_EQ(probe[k].sum[c], q.sum[c]) << k;
        }

        // The probe grew after the last pass (the first pass's draw lacks pixels it holds), and the pixels it
        // added were rendered over all three passes above, beside the others.
        backend->reset();
        RenderLimits firstPass = plain;
        firstPass.passes = 1;
        renderProgressive(*backend, frame, firstPass);
        std::vector<AccumPixel> first;
        backend->readAccumulation(first);
        const ErrorProbe drawn = designProbe(first, w, h, frame.seed);
        EXPECT_GT(outcome.probe.pixels.size(), drawn.pixels.size());
        EXPECT_TRUE(std::includes(outcome.probe.pixels.begin(), outcome.probe.pixels.end(), drawn.pixels.begin(),
                                  drawn.pixels.end()));

        // A frame whose pixels are not the allocated accumulation's is refused, not rendered out of bounds.
        EXPECT_THROW(backend->renderPasses(makeFrameParams(scene, w + 40, h, 9), 0, 1), std::logic_error);
        EXPECT_THROW(backend->resizeProbe({0u, w * h}), std::logic_error);
        backend->resize(w, h);  // forgets the probe's pixels, which were the old image's
        EXPECT_THROW(backend->renderPasses(probeFrame(frame), 0, 1), std::logic_error);
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, ErrorProbeOn, ::testing::Values(BackendChoice::Cpu, BackendChoice::Cuda),
                         [](const ::testing::TestParamInfo<BackendChoice>& info) {
                             return info.param == BackendChoice::Cpu ? "Cpu" : "Cuda";
                         });

}  // namespace
}  // namespace trazo
