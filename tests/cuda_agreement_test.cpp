// CPU and CUDA backends run the same renderSample(): on every shipped scene the CUDA image must agree with the
// CPU's to within what the CPU's own rounding sensitivity predicts for fast math. The CUDA half skips without a
// GPU; the scene list and the calibration of the rule run everywhere (host only).
//
// Why these tolerances. --use_fast_math (gpu-readiness.md R7) changes rounding, never the algorithm, so a GPU
// pixel differs from the CPU's in two ways:
//  1. Continuously: every operation rounds a little differently. A pixel is a mean of positive terms (≤ 16
//     passes × 50 indirect directions × 100 light cells), each a chain of ≲ 100 operations from the camera;
//     the GPU's approximate div/sqrt/rcp are within 2 ulp (2^-22) where the host is within ½ ulp, so a
//     well-conditioned term moves by ≲ 100 × 2.5 × 2^-23 ≈ 2^-15 relative and the float sums of ≲ 170 terms
//     add ≲ 170 × 2^-24 ≈ 2^-16.6 per side: ≈ 2^-14.3 in all. kContinuousRel = 2^-12 leaves a factor 5 for
//     longer chains; factors near 0 (a grazing cosine) carry absolute, not relative, error, hence the floor
//     kContinuousAbs = 2^-14 of unit radiance. A pixel beyond that bound has "flipped".
//  2. Discretely: a decision whose margin is below the rounding error (a shadow ray grazing an edge, a BVH,
//     CSG or total-internal-reflection choice, a ray hitting exactly where two faces meet) goes the other
//     way and the pixel changes by a lot. Which decisions sit that close is a property of the scene, so the
//     CPU measures it on itself: it renders the scene scaled about the origin by 1 + 7·2^-23 and by
//     1 − 5·2^-23 (scaleSceneAboutOrigin: the same image in exact arithmetic; every coordinate and every
//     operation after it re-rounded, ≤ 1 ulp apart per operation, exact zeros kept exact as on the GPU).
//     The pixels either nudge flips are `undecided`: the rounding decides them, so the GPU may flip any.
//     Elsewhere a flip needs a near-tie, and the number a perturbation finds is proportional to its size: a
//     nudge finds m new ones (the mean, over the two, of its flips outside the other's), so the GPU, whose
//     per-operation discrepancy is at most kFastMathFactor times a nudge's, finds ≤ kFastMathFactor × m.
//     The factor 8: sin/cos.approx (the glossy and indirect directions) err by 2^-21.41 absolute on values
//     in [½, 1), ≈ 6 ulp there, + ½ ulp on the host, against a nudge's ≤ 1 ulp (div.approx: 2.5 against 1);
//     8 is the next power of two. m is itself a count, so it enters as its Poisson upper bound (z = 3).
//     The RMSE budget follows from the same counts: the continuous bound over the image plus every allowed
//     flip at the largest squared jump a nudge made (a flip swaps the same kind of decision on the GPU), or,
//     if no nudge flipped anything, at the largest jump an image can make (a pixel between 0 and the peak).
//     Bounds and budgets come from the CPU image alone, so a wild GPU image cannot widen them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <string>
#include <thread>
#include <vector>

#include "backends/backend.h"
#include "fetched_assets.h"
#include "render_harness.h"
#include "scene/scene.h"
#include "test_paths.h"

namespace trazo::test {
namespace {

// Every scene in scenes/: ShippedScenesAreAllListed fails when a new one is not added here.
const char* const kShippedScenes[] = {
    "cornell_box.scene",
    "effect_depth_of_field.scene",   "effect_dispersion.scene",      "effect_fresnel.scene",
    "effect_gallery.scene",          "effect_rough_glass.scene",     "effect_subsurface.scene",
    "extra1_refract_indirect.scene", "path_gallery.scene",           "scene10_bunny_indirect.scene", "scene10_bunny_indirect_area.scene",
    "scene1_area.scene",             "scene1_point.scene",           "scene2_bunny.scene",
    "scene2_bunny_point.scene",      "scene3_csg.scene",             "scene3_csg_area.scene",
    "scene4_reflect.scene",          "scene5_bunny_reflect.scene",   "scene6_glossy.scene",
    "scene7_refract.scene",          "scene8_diffuse_only.scene",    "scene8_normal_only.scene",
    "scene8_textured_mesh.scene",    "scene8_untextured.scene",      "scene9_indirect.scene",
    "scene9_indirect_point.scene",
};

// Small enough for the CPU (a few seconds for all scenes and nudges), large enough for counts of pixels.
constexpr int kSize = 128;
constexpr uint32_t kPasses = 16;
constexpr uint32_t kSeed = 5;

constexpr double kContinuousRel = 0x1p-12;
constexpr double kContinuousAbs = 0x1p-14;
constexpr double kFastMathFactor = 8.0;
constexpr double kPoissonZ = 3.0;
constexpr double kNudges[2] = {1.0 + 7 * 0x1p-23, 1.0 - 5 * 0x1p-23};
constexpr double kThirdNudge = 1.0 + 11 * 0x1p-23;  // only for the calibration test

RenderRequest smallRequest(BackendChoice backend) {
    const unsigned threads = std::max(2u, std::thread::hardware_concurrency());
    return {.passes = kPasses, .threads = threads, .seed = kSeed, .backend = backend, .width = kSize, .height = kSize};
}

RenderedImage renderNudged(const std::string& path, double factor) {
    RenderRequest request = smallRequest(BackendChoice::Cpu);
    request.editScene = [factor](Scene& scene) { scaleSceneAboutOrigin(scene, factor); };
    return renderSceneFile(path, request);
}

// The most rounding alone can move a pixel whose CPU value is `reference` (channel by channel).
double continuousBound(Vec3 reference) { return kContinuousRel * maxComponent(reference) + kContinuousAbs; }

// NaN-safe: a NaN or infinite channel counts as flipped.
bool flipped(Vec3 reference, Vec3 other) {
    const double bound = continuousBound(reference);
    for (int c = 0; c < 3; ++c)
        if (!(std::fabs(double(reference[c]) - double(other[c])) <= bound)) return true;
    return false;
}

double squaredJump(Vec3 a, Vec3 b) {
    const Vec3 d = a - b;
    return double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
}

std::vector<bool> flips(const RenderedImage& a, const RenderedImage& b) {
    std::vector<bool> out(a.pixels.size());
    for (size_t i = 0; i < out.size(); ++i) out[i] = flipped(a.pixels[i], b.pixels[i]);
    return out;
}

size_t countOutside(const std::vector<bool>& flipsOf, const std::vector<bool>& excluded) {
    size_t n = 0;
    for (size_t i = 0; i < flipsOf.size(); ++i) n += flipsOf[i] && !excluded[i];
    return n;
}

// Wilson–Hilferty upper bound on the mean of a Poisson count observed as `count` (z standard deviations).
double poissonUpper(double count, double z) {
    const double n = count + 1.0;
    return n * std::pow(1.0 - 1.0 / (9.0 * n) + z / (3.0 * std::sqrt(n)), 3.0);
}

// What re-rounding the CPU's own computation changes in one scene's image.
struct Sensitivity {
    std::vector<bool> undecided;   // pixels either nudge flipped
    size_t undecidedCount = 0;
    double newFlips = 0.0;         // m: mean flips of one nudge outside the other's
    double worstJumpSquared = 0.0; // over the nudges' flipped pixels, all channels
    double nudgeRmse = 0.0;        // the larger of the two nudges' RMSE against the image
};

Sensitivity measureSensitivity(const RenderedImage& cpu, const RenderedImage nudged[2]) {
    Sensitivity s;
    const std::vector<bool> f0 = flips(cpu, nudged[0]), f1 = flips(cpu, nudged[1]);
    s.undecided.resize(f0.size());
    for (size_t i = 0; i < f0.size(); ++i) {
        s.undecided[i] = f0[i] || f1[i];
        s.undecidedCount += s.undecided[i];
        if (f0[i]) s.worstJumpSquared = std::max(s.worstJumpSquared, squaredJump(cpu.pixels[i], nudged[0].pixels[i]));
        if (f1[i]) s.worstJumpSquared = std::max(s.worstJumpSquared, squaredJump(cpu.pixels[i], nudged[1].pixels[i]));
    }
    s.newFlips = 0.5 * double(countOutside(f0, f1) + countOutside(f1, f0));
    s.nudgeRmse = std::max(rmse(cpu, nudged[0]), rmse(cpu, nudged[1]));
    return s;
}

struct Budget {
    double flipsOutside;  // flips allowed outside the undecided pixels
    double rmse;
};

Budget agreementBudget(const RenderedImage& cpu, const Sensitivity& s, double fastMathFactor) {
    double continuousSquared = 0.0, peak = 0.0;  // from the CPU image alone: `other` cannot widen its budget
    for (const Vec3& p : cpu.pixels) {
        const double bound = continuousBound(p);
        continuousSquared += bound * bound;  // per channel: at most the pixel's bound
        peak = std::max(peak, double(maxComponent(p)));
    }
    Budget b;
    b.flipsOutside = fastMathFactor * poissonUpper(s.newFlips, kPoissonZ);
    const double jumpSquared = s.undecidedCount > 0 ? s.worstJumpSquared : 3.0 * peak * peak;
    const double flipsSquared = (double(s.undecidedCount) + b.flipsOutside) * jumpSquared / 3.0;
    b.rmse = std::sqrt((continuousSquared + flipsSquared) / double(cpu.pixels.size()));
    return b;
}

// `other` agrees with `cpu` when it flips no more pixels outside the undecided ones than the budget allows and
// its RMSE is within the budget's.
::testing::AssertionResult agreesWithin(const RenderedImage& cpu, const RenderedImage& other, const Sensitivity& s,
                                        double fastMathFactor) {
    if (cpu.pixels.empty() || cpu.pixels.size() != other.pixels.size())
        return ::testing::AssertionFailure() << "images of " << cpu.pixels.size() << " and " << other.pixels.size()
                                             << " pixels";
    const std::vector<bool> f = flips(cpu, other);
    const size_t outside = countOutside(f, s.undecided);
    const size_t total = std::count(f.begin(), f.end(), true);
    const double error = rmse(cpu, other);
    const Budget b = agreementBudget(cpu, s, fastMathFactor);
    const bool ok = double(outside) <= b.flipsOutside && error <= b.rmse;  // false for a NaN RMSE
    char text[320];
    std::snprintf(text, sizeof text,
                  "%zu flipped pixels (%zu outside the %zu undecided; budget %.1f), RMSE %.3g (budget %.3g); "
                  "CPU sensitivity: %.1f new flips per nudge, nudge RMSE %.3g",
                  total, outside, s.undecidedCount, b.flipsOutside, error, b.rmse, s.newFlips, s.nudgeRmse);
    return (ok ? ::testing::AssertionSuccess() : ::testing::AssertionFailure()) << text;
}

std::string withoutExtension(const std::string& scene) { return scene.substr(0, scene.find('.')); }

TEST(CudaAgreementScenes, ShippedScenesAreAllListed) {
    const std::vector<std::string> listed(std::begin(kShippedScenes), std::end(kShippedScenes));
    std::vector<std::string> sorted = listed;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, listed) << "keep kShippedScenes sorted";
    EXPECT_EQ(shippedSceneFiles(), sorted) << "every scene in scenes/ must be in kShippedScenes";
}

class CudaAgreement : public ::testing::TestWithParam<const char*> {
    void SetUp() override {
        const std::string why = absentFetchedAsset(sourcePath(std::string("scenes/") + GetParam()));
        if (!why.empty()) GTEST_SKIP() << why;
    }
};

TEST_P(CudaAgreement, SameImageAsCpu) {
    std::string device;
    if (!cudaDeviceAvailable(device))
        GTEST_SKIP() << "no CUDA device (" << (device.empty() ? "this build has no CUDA backend" : device)
                     << "): CPU/CUDA agreement of " << GetParam() << " not checked";
    const std::string path = sourcePath(std::string("scenes/") + GetParam());
    const RenderedImage cpu = renderSceneFile(path, smallRequest(BackendChoice::Cpu));
    const RenderedImage nudged[2] = {renderNudged(path, kNudges[0]), renderNudged(path, kNudges[1])};
    const RenderedImage gpu = renderSceneFile(path, smallRequest(BackendChoice::Cuda));
    const ::testing::AssertionResult verdict = agreesWithin(cpu, gpu, measureSensitivity(cpu, nudged), kFastMathFactor);
    std::printf("[ agreement ] %s on %s: %s\n", GetParam(), device.c_str(), verdict.message());
    EXPECT_TRUE(verdict);
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, CudaAgreement, ::testing::ValuesIn(kShippedScenes),
                         [](const ::testing::TestParamInfo<const char*>& info) { return withoutExtension(info.param); });

// The rule on the CPU alone, on scenes that between them have ties at pixel centres, refraction, indirect
// light, a mesh, textures and a normal map: the nudges do re-round every pixel and find the rounding-decided
// ones where a scene has them; a third nudge passes without the fast-math factor (the rule is not too tight
// for CPU against CPU); errors a bug would make fail with it (the rule is not vacuous).
struct CalibrationCase {
    const char* scene;
    // Edges that pixel centres hit exactly: in the Cornell boxes of scenes 1–5, 9 and 10 (camera on the axis,
    // square image) the image diagonals meet the seams of two walls, 100 pixels at 128².
    bool hasTies;
};

void PrintTo(const CalibrationCase& c, std::ostream* os) { *os << c.scene; }  // for gtest's test listing

class CudaAgreementRule : public ::testing::TestWithParam<CalibrationCase> {};

TEST_P(CudaAgreementRule, CalibratedOnTheCpu) {
    const std::string path = sourcePath(std::string("scenes/") + GetParam().scene);
    const RenderedImage cpu = renderSceneFile(path, smallRequest(BackendChoice::Cpu));
    const RenderedImage nudged[2] = {renderNudged(path, kNudges[0]), renderNudged(path, kNudges[1])};
    const Sensitivity s = measureSensitivity(cpu, nudged);
    std::printf("[ sensitivity ] %s: %zu undecided pixels, %.1f new flips per nudge, nudge RMSE %.3g\n",
                GetParam().scene, s.undecidedCount, s.newFlips, s.nudgeRmse);
    EXPECT_GT(s.nudgeRmse, 0.0) << "a nudge that changes nothing measures nothing";
    if (GetParam().hasTies) {
        EXPECT_GT(s.undecidedCount, 0u) << "the nudges missed the scene's ties";
    }

    EXPECT_TRUE(agreesWithin(cpu, renderNudged(path, kThirdNudge), s, 1.0)) << "a third nudge";

    RenderRequest otherSeed = smallRequest(BackendChoice::Cpu);
    otherSeed.seed = kSeed + 1;  // a device that draws the wrong samples
    EXPECT_FALSE(agreesWithin(cpu, renderSceneFile(path, otherSeed), s, kFastMathFactor)) << "another seed";

    RenderRequest widerView = smallRequest(BackendChoice::Cpu);
    widerView.editScene = [](Scene& scene) { scene.camera.fovDegrees *= 1.0f + 0x1p-10f; };  // 2^13 ulp
    EXPECT_FALSE(agreesWithin(cpu, renderSceneFile(path, widerView), s, kFastMathFactor)) << "a 0.1 % wider view";
}

INSTANTIATE_TEST_SUITE_P(SeedScenes, CudaAgreementRule,
                         ::testing::Values(CalibrationCase{"scene1_area.scene", true},
                                           CalibrationCase{"scene7_refract.scene", true},
                                           CalibrationCase{"scene9_indirect.scene", true},
                                           CalibrationCase{"scene8_textured_mesh.scene", false}),
                         [](const ::testing::TestParamInfo<CalibrationCase>& info) {
                             return withoutExtension(info.param.scene);
                         });

}  // namespace
}  // namespace trazo::test
