// Every render states its error, and honestly: on every seed scene the default render's own estimate (the
// error probe, render/error_probe.h) lies within a factor of 1.5 of its true error, measured against a
// converged reference rendered with another seed (both as root mean squares over a few seeds). Scenes
// without noise (point lights, mirrors) must say 0.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "flatten/flatten.h"
#include "fetched_assets.h"
#include "render/error_probe.h"
#include "render/frame_setup.h"
#include "render/progressive_render.h"
#include "render/render_plan.h"
#include "scene/scene_reader.h"
#include "test_paths.h"

namespace trazo::test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 72;
constexpr uint32_t kReferenceFactor = 32;  // the reference's passes over the render's

struct Rendered {
    std::vector<Vec3> image;
    ErrorEstimate estimate;
};

// Renders as `trazo --render` does by default (headlessBlocks, the camera path's passes, halves and the probe).
Rendered render(Backend& backend, const Scene& scene, const SceneArrays& arrays, uint32_t seed, uint32_t passes) {
    const StrataBlocks blocks = headlessBlocks(arrays);
    backend.resize(kWidth, kHeight);
    RenderLimits limits;
    limits.passes = passes;
    limits.cyclePasses = fullCyclePasses(arrays, blocks);
    limits.errorProbe = true;
    const RenderOutcome outcome = renderProgressive(backend, makeFrameParams(scene, kWidth, kHeight, seed, blocks), limits);
    Rendered r;
    std::vector<AccumPixel> accum;
    r.estimate = estimateRenderError(backend, outcome.probe, accum);
    r.image = resolveImage(accum);
    return r;
}

class ErrorHonesty : public ::testing::TestWithParam<std::string> {};

TEST_P(ErrorHonesty, DefaultRenderStatesItsTrueErrorWithinAFactorOf1_5) {
    const std::string path = sourcePath("scenes/" + GetParam());
    if (const std::string absent = absentFetchedAsset(path); !absent.empty()) GTEST_SKIP() << absent;
    Diagnostics diags;
    const Scene scene = readSceneFile(path, diags);
    ASSERT_FALSE(diags.hasErrors());
    const SceneArrays arrays = flatten(scene).arrays;
    std::string error;
    auto backend = createBackend(BackendChoice::Cpu, 2, error);
    ASSERT_TRUE(backend) << error;
    backend->upload(arrays);

    const uint32_t passes = defaultPasses(arrays, headlessBlocks(arrays));
    const Rendered reference = render(*backend, scene, arrays, 1000, kReferenceFactor * passes);
    ASSERT_TRUE(reference.estimate.available);
    // One render's error is itself a random number, heavy-tailed where a few pixels carry most of it (a
    // bright indirect path in scene 10: one seed in six measures 0.20 where the others measure 0.12), so the
    // estimate is compared with the root mean square of the true error over kSeeds renders, and likewise.
    constexpr int kSeeds = 4;
    double estimates = 0.0, measures = 0.0;
    for (uint32_t seed = 1; seed <= kSeeds; ++seed) {
        const Rendered image = render(*backend, scene, arrays, seed, passes);
        ASSERT_TRUE(image.estimate.available);
        const double measured = compareToReference(image.image, reference.image).relError;
        estimates += image.estimate.relError * image.estimate.relError / kSeeds;
        measures += measured * measured / kSeeds;
    }
    // The measured error holds the reference's own too: removed in quadrature (it is ~1/√32 of the image's).
    const double refError = reference.estimate.relError;
    const double measured = std::sqrt(measures);
    const double truth = std::sqrt(std::max(0.0, measures - refError * refError));
    const double estimate = std::sqrt(estimates);
    std::printf("%-36s %3u passes: estimated %.3f%%, true %.3f%% (measured %.3f%%, reference %.3f%%)\n",
                GetParam().c_str(), passes, 100.0 * estimate, 100.0 * truth, 100.0 * measured, 100.0 * refError);
    // What the headless render skips the probe for must be noiseless indeed: every seed's image is the
    // reference's, bit for bit, and the estimate of the limits it renders with is 0 exactly.
    if (noSamplingNoise(arrays)) {
        EXPECT_EQ(measured, 0.0);
        RenderLimits limits;
        limits.noiseless = true;
        std::vector<AccumPixel> accum;
        const ErrorEstimate exact = estimateRenderError(*backend, limits, ErrorProbe{}, accum);
        EXPECT_TRUE(exact.available && exact.exact);
        EXPECT_EQ(exact.relError, 0.0);
    }
    if (measured < 1e-6) {  // a noiseless scene: every seed gives the same image, and the estimate must say so
        EXPECT_LT(estimate, 1e-6);
        return;
    }
    // Scene 5's glossy bunny reflects the light rectangle: a rare, very bright sample lands in about one
    // render in four (0.8 % typical, 3–5 % with one). The probe sees it only because it grows after the
    // last pass (growRenderedProbe); drawn from the first pass alone, this estimate was 1.47 % against 2.60 %.
    EXPECT_GT(estimate, truth / 1.5);
    EXPECT_LT(estimate, truth * 1.5);
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = std::filesystem::path(info.param).stem().string();
    for (char& c : name)
        if (!std::isalnum((unsigned char)c)) c = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(SeedScenes, ErrorHonesty, ::testing::ValuesIn(shippedSceneFiles()), testName);

}  // namespace
}  // namespace trazo::test
