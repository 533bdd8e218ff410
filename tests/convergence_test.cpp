// Convergence tools on a real render: the estimated error brackets the measured one, --target-error stops
// near its target, the CLI reports the estimate, and the benchmark's log–log slope is about −1/2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "flatten/flatten.h"
#include "scene/scene_reader.h"
#include "support/convergence_series.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace trazo::test {
namespace {

using namespace trazo::convergence;

const std::string kPenumbraScene =
    penumbraSceneText("    RenderWidth 40\n    RenderHeight 30\n    IndirectQuality 0\n");

class Convergence : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        Diagnostics diags;
        scene_ = std::make_unique<Scene>(readSceneText(kPenumbraScene, tempPath("penumbra.scene"), diags));
        ASSERT_FALSE(diags.hasErrors());
        arrays_ = std::make_unique<SceneArrays>(flatten(*scene_).arrays);
        std::string error;
        backend_ = createBackend(BackendChoice::Cpu, 2, error);
        ASSERT_TRUE(backend_) << error;
        reference_ = std::make_unique<Reference>(renderReference(*backend_, *scene_, *arrays_, 40, 30, 8192, 77));
    }
    static void TearDownTestSuite() {
        backend_.reset();
        reference_.reset();
        arrays_.reset();
        scene_.reset();
    }
    static std::unique_ptr<Scene> scene_;
    static std::unique_ptr<SceneArrays> arrays_;
    static std::unique_ptr<Backend> backend_;
    static std::unique_ptr<Reference> reference_;
};
std::unique_ptr<Scene> Convergence::scene_;
std::unique_ptr<SceneArrays> Convergence::arrays_;
std::unique_ptr<Backend> Convergence::backend_;
std::unique_ptr<Reference> Convergence::reference_;

TEST_F(Convergence, SceneIsNoisyWithACycleOf16) {
    EXPECT_EQ(fullCyclePasses(*arrays_, StrataBlocks::ones()), 16u);
    EXPECT_LT(reference_->estRelError, 0.004) << "the reference must be far better than what is measured";
}

TEST_F(Convergence, EstimateBracketsTheTrueError) {
    SeriesRequest req;
    req.width = 40, req.height = 30, req.seed = 5, req.maxPasses = 1024;
    const std::vector<ConvergencePoint> points = runSeries(*backend_, *scene_, *arrays_, *reference_, req);
    int checked = 0;
    for (const ConvergencePoint& p : points) {
        if (!p.balanced) continue;  // where the halves are equally stratified (multiples of 2 cycles)
        EXPECT_GT(p.estRelError, p.trueRelError / 1.5) << p.passes << " passes";
        EXPECT_LT(p.estRelError, p.trueRelError * 1.5) << p.passes << " passes";
        ++checked;
    }
    EXPECT_GE(checked, 6);  // 32, 64, …, 1024
}

// The slope of the benchmark's own curve: error against render time on log–log axes, past one cycle (where
// stratification no longer lets the error fall faster than Monte Carlo's 1/√n). Timing on a shared machine
// is noisy, so the band is wider than for passes.
TEST_F(Convergence, LogLogSlopeIsAboutMinusOneHalf) {
    SeriesRequest req;
    req.width = 40, req.height = 30, req.seed = 9, req.maxPasses = 2048;
    const std::vector<ConvergencePoint> points = runSeries(*backend_, *scene_, *arrays_, *reference_, req);
    // The benchmark's slope fit, against passes rather than seconds (a wall-clock slope flaked under a loaded
    // ctest -j2): time proportional to passes. The band is the issue's −0.6 … −0.4.
    std::vector<ConvergencePoint> evenlyTimed = points;
    for (ConvergencePoint& p : evenlyTimed) p.seconds = 0.001 * p.passes;
    const double passSlope = logLogSlope(evenlyTimed, 32);
    EXPECT_LT(passSlope, -0.4);
    EXPECT_GT(passSlope, -0.6);
    // Times to reach an error are ordered and interpolated between measured points.
    const double t5 = timeToReach(points, 0.05), t2 = timeToReach(points, 0.02);
    ASSERT_TRUE(std::isfinite(t5) && std::isfinite(t2));
    EXPECT_LE(t5, t2);
    EXPECT_TRUE(std::isnan(timeToReach(points, 1e-6)));
}

TEST_F(Convergence, TargetErrorStopsNearTheTarget) {
    for (double target : {0.04, 0.015}) {
        backend_->upload(*arrays_);
        backend_->resize(40, 30);
        RenderLimits limits;
        limits.passes = kMaxProgressivePasses;
        limits.cyclePasses = fullCyclePasses(*arrays_, StrataBlocks::ones());
        limits.targetError = target;
        const RenderOutcome out = renderProgressive(*backend_, makeFrameParams(*scene_, 40, 30, 3), limits);
        ASSERT_TRUE(out.reachedTarget);
        const ReferenceError r = compareToReference(readImage(*backend_), reference_->image);
        const double truth = std::sqrt(r.relError * r.relError - reference_->estRelError * reference_->estRelError);
        EXPECT_LT(truth, 1.3 * target) << out.passes << " passes";
        EXPECT_GT(truth, 0.5 * target) << out.passes << " passes: went on far longer than needed";
    }
}

// trazo --render `scene` with `options` and --stats: the exit status; the stats in `json`, stderr in `errors`.
int renderStats(const std::string& scene, const std::string& options, std::string& json, std::string& errors) {
    const std::string stats = tempPath("cli_stats.json");
    std::remove(stats.c_str());
    CommandResult r = runTrazo("--render " + scene + " -o " + tempPath("cli_render.png") + " --stats " + stats + " " +
                               options);
    json = readFileText(stats);
    errors = std::move(r.errors);
    return r.status;
}

double jsonNumber(const std::string& json, const std::string& key) {
    const size_t at = json.find("\"" + key + "\": ");
    if (at == std::string::npos) return NAN;
    return std::atof(json.c_str() + at + key.size() + 4);
}

TEST(ConvergenceCli, StatsReportTheEstimateAndTargetErrorStops) {
    const std::string scene = writeTempFile("cli_penumbra.scene", kPenumbraScene);
    std::string json, errors;
    ASSERT_EQ(renderStats(scene, "--spp 64", json, errors), 0) << errors;
    const double estimate = jsonNumber(json, "estimated_rel_error");
    EXPECT_GT(estimate, 0.001) << json;
    EXPECT_LT(estimate, 0.2) << json;
    EXPECT_NE(json.find("\"estimate_balanced\": true"), std::string::npos) << json;
    EXPECT_NE(errors.find("estimated relative error"), std::string::npos) << errors;

    // One stratum per pass (a 16-pass cycle), and the default blocks (the whole light per pass: a 1-pass cycle).
    for (const char* blocks : {"--blocks 1", ""}) {
        ASSERT_EQ(renderStats(scene, std::string("--target-error 0.03 --quiet ") + blocks, json, errors), 0) << errors;
        EXPECT_NE(json.find("\"reached_target\": true"), std::string::npos) << json;
        EXPECT_LE(jsonNumber(json, "estimated_rel_error"), 0.03) << json;
        const double spp = jsonNumber(json, "spp"), cycle = jsonNumber(json, "full_cycle_spp");
        EXPECT_EQ(cycle, *blocks ? 16.0 : 1.0) << json;
        EXPECT_GT(spp, 1.0) << "a 3 % target needs more than one pass here: " << json;
        // 40 × 30: a quarter of the pixels at the base chance (~300), plus the brightest.
        EXPECT_GT(jsonNumber(json, "error_probe_pixels"), 200.0) << json;
        EXPECT_LT(jsonNumber(json, "error_probe_pixels"), 500.0) << json;
    }

    // One pass states its error too (the error probe), and a loose target is met by the first pass.
    ASSERT_EQ(renderStats(scene, "--spp 1 --fixed-grid --quiet", json, errors), 0) << errors;
    EXPECT_GT(jsonNumber(json, "estimated_rel_error"), 0.001) << json;
    EXPECT_LT(jsonNumber(json, "estimated_rel_error"), 0.2) << json;
    EXPECT_NE(json.find("\"estimate_balanced\": true"), std::string::npos) << json;
    EXPECT_NE(json.find("\"fixed_grid\": true"), std::string::npos) << json;
    ASSERT_EQ(renderStats(scene, "--target-error 0.5 --quiet", json, errors), 0) << errors;
    EXPECT_NE(json.find("\"reached_target\": true"), std::string::npos) << json;
    EXPECT_EQ(jsonNumber(json, "spp"), 1.0) << json;
}

// A render that draws no random number (point light, one centred position) states 0 exactly, draws no probe,
// and meets any target error with its first pass.
TEST(ConvergenceCli, ANoiselessRenderStatesZeroWithoutAProbe) {
    const std::string scene = sourcePath("scenes/scene1_point.scene");
    std::string json, errors;
    ASSERT_EQ(renderStats(scene, "--width 64 --height 48", json, errors), 0) << errors;
    EXPECT_EQ(jsonNumber(json, "estimated_rel_error"), 0.0) << json;
    EXPECT_EQ(jsonNumber(json, "error_probe_pixels"), 0.0) << json;
    EXPECT_NE(json.find("\"no_sampling_noise\": true"), std::string::npos) << json;
    EXPECT_NE(json.find("\"estimate_balanced\": true"), std::string::npos) << json;
    EXPECT_NE(errors.find("relative error 0 (no sampling noise"), std::string::npos) << errors;
    ASSERT_EQ(renderStats(scene, "--width 64 --height 48 --target-error 0.0001 --quiet", json, errors), 0) << errors;
    EXPECT_NE(json.find("\"reached_target\": true"), std::string::npos) << json;
    EXPECT_EQ(jsonNumber(json, "spp"), 1.0) << json;
    // A scene with noise keeps its probe.
    ASSERT_EQ(renderStats(sourcePath("scenes/scene1_area.scene"), "--width 64 --height 48 --quiet", json, errors), 0)
        << errors;
    EXPECT_GT(jsonNumber(json, "error_probe_pixels"), 0.0) << json;
    EXPECT_NE(json.find("\"no_sampling_noise\": false"), std::string::npos) << json;
}

}  // namespace
}  // namespace trazo::test
