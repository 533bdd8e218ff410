// The error probe: its lattice, its estimate against a known variance, and the backend rendering exactly the
// lattice's pixels with the probe's seed.
#include "render/error_probe.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "device/flatten.h"
#include "render/frame_setup.h"
#include "render/progressive_render.h"
#include "scene/scene_reader.h"

namespace trazo {
namespace {

TEST(ErrorProbe, LatticeCoversTheImageAtAboutTheTargetPixelCount) {
    for (const auto& [w, h] : std::vector<std::pair<uint32_t, uint32_t>>{
             {512, 512}, {1920, 1080}, {96, 72}, {40, 30}, {1, 1}, {3, 1}, {7000, 5}, {8192, 8192}}) {
        for (uint32_t seed : {0u, 1u, 12345u}) {
            const PixelLattice l = probeLattice(w, h, seed);
            SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + " seed " + std::to_string(seed));
            EXPECT_GE(l.stride, kProbeMinStride);
            ASSERT_GE(l.width, 1u);
            ASSERT_GE(l.height, 1u);
            // The last lattice pixel lies inside the image, the next one outside.
            EXPECT_LT(l.offsetX + l.stride * (l.width - 1), w);
            EXPECT_GE(l.offsetX + l.stride * l.width, w);
            EXPECT_LT(l.offsetY + l.stride * (l.height - 1), h);
            EXPECT_GE(l.offsetY + l.stride * l.height, h);
            const double pixels = double(l.width) * l.height;
            if (double(w) * h >= 4.0 * kProbeTargetPixels * 4.0) {  // large images: about the target, ≤ 2 % work
                EXPECT_GT(pixels, 0.7 * kProbeTargetPixels);
                EXPECT_LT(pixels, 2.5 * kProbeTargetPixels);
                EXPECT_LE(pixels / (double(w) * h), 0.02);
            }
        }
    }
    EXPECT_EQ(probeLattice(512, 512, 0).stride, 8u);
    EXPECT_NE(probeFrame(FrameParams{}, probeLattice(64, 64, 0)).seed, FrameParams{}.seed);
}

// Image and probe pixels drawn independently from N(mu, sigma²) per channel: the estimate recovers sigma.
TEST(ErrorProbe, EstimateRecoversAKnownVariance) {
    const uint32_t width = 256, height = 256;
    const PixelLattice lattice = probeLattice(width, height, 3);
    std::mt19937 rng(11);
    std::normal_distribution<double> noise(0.0, 0.05);
    auto sample = [&](AccumPixel& p, double mu, double passes) {
        p.count = passes;
        for (int c = 0; c < 3; ++c) p.sum[c] = passes * (mu + noise(rng));
    };
    std::vector<AccumPixel> image((size_t)width * height), probe((size_t)lattice.width * lattice.height);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) sample(image[(size_t)y * width + x], 0.1 + 0.8 * x / width, 4.0);
    for (uint32_t j = 0; j < lattice.height; ++j)
        for (uint32_t i = 0; i < lattice.width; ++i)
            sample(probe[(size_t)j * lattice.width + i], 0.1 + 0.8 * (lattice.offsetX + lattice.stride * i) / width, 4.0);
    const ErrorEstimate e = estimateErrorWithProbe(image, width, lattice, probe);
    ASSERT_TRUE(e.available);
    EXPECT_EQ(e.probePixels, lattice.width * lattice.height);
    // n = 3·1024 values of σ²χ²₁: the MSE estimate's relative deviation is √(2/n) = 2.6 %, so 10 % on the
    // RMSE (20 % on the MSE) is a 7σ bound.
    EXPECT_NEAR(e.rmse, 0.05, 0.005);
    EXPECT_NEAR(e.meanValue, 0.5, 0.01);
    EXPECT_NEAR(e.relError, 0.1, 0.01);

    // A probe that did not render the image's passes gives no estimate.
    probe[5].count = 3.0;
    EXPECT_FALSE(estimateErrorWithProbe(image, width, lattice, probe).available);
    EXPECT_FALSE(estimateErrorWithProbe(image, width, lattice, {}).available);
}

const char* kAreaLightScene =
    "SceneSettings\n{\n    RenderWidth 37\n    RenderHeight 23\n    IndirectQuality 0\n    Antialiasing 4\n}\n"
    "Camera\n{\n    POV 0 3 8\n    POI 0 1 0\n    FOV 45\n}\n"
    "Material\n{\n    Name white\n    DiffuseColor 0.8 0.8 0.8\n}\n"
    "Box\n{\n    Material white\n    Scale 8 0.2 8\n    Translation 0 -0.1 0\n}\n"
    "Sphere\n{\n    Material white\n    Center 0 1 0\n    Radius 1\n}\n"
    "AreaLight\n{\n    Position 0.5 4 0\n    Direction 0 -1 0\n    Width 3\n    Height 3\n    Subdivision 4 4\n"
    "    Color 1 1 1\n}\n";

// The probe's pixel (i, j) is bit for bit the image pixel (offsetX + stride·i, offsetY + stride·j) of a render
// with the probe's seed: the lattice maps the right pixels and the probe is the image's own estimator.
class ErrorProbeOn : public ::testing::TestWithParam<BackendChoice> {};

TEST_P(ErrorProbeOn, BackendRendersTheLatticePixelsWithTheProbeSeed) {
    const BackendChoice choice = GetParam();
    std::string device;
    if (choice == BackendChoice::Cuda && !cudaDeviceAvailable(device))
        GTEST_SKIP() << "no CUDA device (" << (device.empty() ? "this build has no CUDA backend" : device)
                     << "): the CUDA probe's lattice is not checked";
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
        limits.probe = probeLattice(w, h, 9);
        backend->resizeProbe(limits.probe);
        renderProgressive(*backend, frame, limits);
        std::vector<AccumPixel> probe;
        backend->readProbe(probe);

        // The same passes as an image, with the probe's seed.
        backend->reset();
        FrameParams asImage = probeFrame(frame, limits.probe);
        asImage.lattice = PixelLattice{};
        RenderLimits plain = limits;
        plain.probe = PixelLattice{};
        renderProgressive(*backend, asImage, plain);
        std::vector<AccumPixel> image;
        backend->readAccumulation(image);
        ASSERT_EQ(probe.size(), (size_t)limits.probe.width * limits.probe.height);
        for (uint32_t j = 0; j < limits.probe.height; ++j)
            for (uint32_t i = 0; i < limits.probe.width; ++i) {
                const AccumPixel& p = probe[(size_t)j * limits.probe.width + i];
                const AccumPixel& q = image[(size_t)(limits.probe.offsetY + limits.probe.stride * j) * w +
                                            limits.probe.offsetX + limits.probe.stride * i];
                ASSERT_EQ(p.count, 3.0);
                for (int c = 0; c < 3; ++c) ASSERT_EQ(p.sum[c], q.sum[c]) << i << "," << j;
            }

        // A frame whose pixels are not the allocated accumulation's is refused, not rendered out of bounds.
        FrameParams wrong = probeFrame(frame, probeLattice(w + 40, h, 9));
        EXPECT_THROW(backend->renderPasses(wrong, 0, 1), std::logic_error);
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, ErrorProbeOn, ::testing::Values(BackendChoice::Cpu, BackendChoice::Cuda),
                         [](const ::testing::TestParamInfo<BackendChoice>& info) {
                             return info.param == BackendChoice::Cpu ? "Cpu" : "Cuda";
                         });

}  // namespace
}  // namespace trazo
