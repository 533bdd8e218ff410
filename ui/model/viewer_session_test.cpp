// Tests of the viewer's model without a window: edits re-flatten and re-upload (or only reset, for the camera),
// resizing reallocates, batches run on the worker and add up to exactly the headless render's image.
#include "model/viewer_session.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "render/frame_setup.h"
#include "render/progressive_render.h"
#include "render/strata_plan.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace trazo {
namespace {

// Records what the session asks of a backend (no rendering).
class RecordingBackend final : public Backend {
public:
    struct Calls {
        int upload = 0, resize = 0, reset = 0, render = 0;
        uint32_t width = 0, height = 0, passes = 0;
        ArrayMask lastChanged = kNoArrays;  // of the last upload
        bool failUploads = false;
        SceneArrays lastUpload;
        FrameParams lastFrame{};
    };
    explicit RecordingBackend(Calls& calls, bool throwOnRender = false) : calls_(calls), throw_(throwOnRender) {}
    std::string name() const override { return "recording"; }
    std::string deviceName() const override { return "test"; }
    void upload(const SceneArrays& arrays) override { upload(arrays, kAllArrays); }
    void upload(const SceneArrays& arrays, ArrayMask changed) override {
        if (calls_.failUploads) throw std::runtime_error("out of device memory");
        ++calls_.upload;
        calls_.lastUpload = arrays;
        calls_.lastChanged = changed;
    }
    void resize(uint32_t width, uint32_t height) override {
        ++calls_.resize;
        calls_.width = width;
        calls_.height = height;
    }
    void reset() override { ++calls_.reset; }
    void renderPasses(const FrameParams& frame, uint32_t, uint32_t count) override {
        if (throw_) throw std::runtime_error("device lost");
        ++calls_.render;
        calls_.passes += count;
        calls_.lastFrame = frame;
    }
    void readAccumulation(std::vector<AccumPixel>& out) override { out.assign(size_t(calls_.width) * calls_.height, {}); }
    uint64_t raysTraced() const override { return 0; }
    double traceRays(const std::vector<RayQuery>& queries, RayQueryKind, std::vector<RayAnswer>& out) override {
        out.assign(queries.size(), RayAnswer{INFINITY, kMissAnswer});  // the session never asks
        return 0.0;
    }
    using Backend::traceRays;

private:
    Calls& calls_;
    bool throw_;
};

TEST(ViewerSession, StartsUploadedSizedAndClear) {
    RecordingBackend::Calls calls;
    ViewerSession session(test::readSourceScene("scenes/scene1_area.scene"), std::make_unique<RecordingBackend>(calls), 0, 40, 30);
    EXPECT_EQ(calls.upload, 1);
    EXPECT_EQ(calls.resize, 1);
    EXPECT_EQ(calls.width, 40u);
    EXPECT_EQ(calls.height, 30u);
    EXPECT_GE(calls.reset, 1);
    EXPECT_EQ(session.accumulation().passes(), 0u);
    EXPECT_EQ(session.accumulation().cyclePasses(), 100u);  // the 10×10 area light
}

TEST(ViewerSession, MaterialEditReuploadsAndRestarts) {
    RecordingBackend::Calls calls;
    ViewerSession session(test::readSourceScene("scenes/scene1_area.scene"), std::make_unique<RecordingBackend>(calls), 0, 16, 16);
    session.renderPasses(3);
    EXPECT_EQ(session.accumulation().passes(), 3u);
    const int uploads = calls.upload, resets = calls.reset, resizes = calls.resize;

    session.scene().materials[1].diffuseColor = Vec3(0.2f, 0.3f, 0.4f);
    session.markDirty(kDirtyScene);
    session.applyEdits();
    EXPECT_EQ(calls.upload, uploads + 1);
    EXPECT_EQ(calls.reset, resets + 1);
    EXPECT_EQ(calls.resize, resizes);  // no reallocation for an edit
    EXPECT_EQ(session.accumulation().passes(), 0u);
    EXPECT_EQ(calls.lastUpload.materials[1].diffuse.y, 0.3f);  // the edit reached the upload
    session.applyEdits();                                            // nothing dirty: nothing done
    EXPECT_EQ(calls.upload, uploads + 1);
    EXPECT_EQ(calls.reset, resets + 1);
}

// The backend is told which arrays changed; a replaced scene that cannot be uploaded leaves the old one.
TEST(ViewerSession, UploadsNameTheChangedArraysAndAFailedReplaceKeepsTheScene) {
    RecordingBackend::Calls calls;
    ViewerSession session(test::readSourceScene("scenes/scene1_area.scene"), std::make_unique<RecordingBackend>(calls), 0, 16, 16);
    EXPECT_EQ(calls.lastChanged, kAllArrays);  // the first upload: everything
    session.scene().materials[1].diffuseColor = Vec3(0.2f, 0.3f, 0.4f);
    session.markDirty(kDirtyScene);
    session.applyEdits();
    EXPECT_EQ(describeArrays(calls.lastChanged), "materials");

    const size_t spheres = session.scene().spheres.size();
    Scene other = test::readSourceScene("scenes/scene3_csg.scene");
    calls.failUploads = true;
    EXPECT_THROW(session.replaceScene(other), std::runtime_error);
    EXPECT_EQ(session.scene().spheres.size(), spheres);
    EXPECT_EQ(session.fileScene().path, test::readSourceScene("scenes/scene1_area.scene").path);
    EXPECT_EQ(session.renderWidth(), 16u);
    calls.failUploads = false;
    session.renderPasses(1);  // the next batch re-sends the old scene whole (the backend may hold part of either)
    EXPECT_EQ(calls.lastChanged, kAllArrays);
    EXPECT_EQ(calls.lastUpload.spheres.size(), spheres);
    EXPECT_EQ(session.accumulation().passes(), 1u);
}

TEST(ViewerSession, CameraEditResetsWithoutUpload) {
    RecordingBackend::Calls calls;
    ViewerSession session(test::readSourceScene("scenes/scene1_area.scene"), std::make_unique<RecordingBackend>(calls), 0, 16, 16);
    session.renderPasses(2);
    const int uploads = calls.upload, resets = calls.reset;
    session.scene().camera.pov = Vec3(1, 5, 15);
    session.markDirty(kDirtyCamera);
    session.renderPasses(1);  // applies the edit first
    EXPECT_EQ(calls.upload, uploads);
    EXPECT_EQ(calls.reset, resets + 1);
    EXPECT_EQ(session.accumulation().passes(), 1u);
    EXPECT_EQ(calls.lastFrame.camera.origin.x, 1.0f);
}

TEST(ViewerSession, ResizeReallocates) {
    RecordingBackend::Calls calls;
    ViewerSession session(test::readSourceScene("scenes/scene1_area.scene"), std::make_unique<RecordingBackend>(calls), 0, 16, 16);
    session.renderPasses(2);
    session.setRenderSize(16, 16);  // the same size: nothing to do
    EXPECT_EQ(session.dirty(), kDirtyNone);
    session.setRenderSize(24, 12);
    session.applyEdits();
    EXPECT_EQ(calls.resize, 2);
    EXPECT_EQ(calls.width, 24u);
    EXPECT_EQ(calls.height, 12u);
    EXPECT_EQ(session.width(), 24u);
    EXPECT_EQ(session.accumulation().passes(), 0u);
    session.renderPasses(1);
    EXPECT_EQ(calls.lastFrame.camera.width, 24u);
}

TEST(ViewerSession, PreviewRendersSmallerAndFullSizeReturns) {
    RecordingBackend::Calls calls;
    ViewerSession session(test::readSourceScene("scenes/scene1_area.scene"), std::make_unique<RecordingBackend>(calls), 0, 30, 17);
    session.setPreviewDivisor(4);
    session.renderPasses(1);
    EXPECT_EQ(calls.width, 8u);  // rounded up
    EXPECT_EQ(calls.height, 5u);
    EXPECT_EQ(calls.lastFrame.camera.width, 8u);
    EXPECT_EQ(session.renderWidth(), 30u);  // the full size is kept for screenshots and the display
    session.setPreviewDivisor(1);
    session.renderPasses(1);
    EXPECT_EQ(calls.width, 30u);
    EXPECT_EQ(calls.height, 17u);
    EXPECT_EQ(session.accumulation().passes(), 1u);
}

TEST(ViewerSession, BatchesRunOnTheWorkerAndErrorsReachTheCaller) {
    RecordingBackend::Calls calls;
    ViewerSession session(test::readSourceScene("scenes/scene1_area.scene"), std::make_unique<RecordingBackend>(calls), 0, 8, 8);
    std::atomic<int> done{0};
    session.setOnBatchDone([&] { ++done; });
    session.startPasses(5);
    session.waitIdle();
    EXPECT_FALSE(session.busy());
    EXPECT_EQ(session.accumulation().passes(), 5u);
    EXPECT_EQ(calls.passes, 5u);
    EXPECT_EQ(done.load(), 1);
    EXPECT_GE(session.passesForBudget(1e9), 1u);

    RecordingBackend::Calls failing;
    ViewerSession broken(test::readSourceScene("scenes/scene1_area.scene"), std::make_unique<RecordingBackend>(failing, true), 0, 8, 8);
    broken.startPasses(1);
    EXPECT_THROW(broken.waitIdle(), std::runtime_error);
}

// What `trazo --render` makes of the scene at this size, seed, blocks and pass count (halves and windows as
// the CLI splits them).
std::vector<Vec3> headlessImage(const Scene& scene, uint32_t width, uint32_t height, uint32_t seed,
                                const StrataBlocks& blocks, uint32_t passes) {
    std::unique_ptr<Backend> headless = createCpuBackend(2);
    const FlattenResult flat = flatten(scene);
    headless->upload(flat.arrays);
    headless->resize(width, height);
    RenderLimits limits;
    limits.passes = passes;
    limits.cyclePasses = fullCyclePasses(flat.arrays, blocks);
    renderProgressive(*headless, makeFrameParams(scene, width, height, seed, blocks), limits);
    return readImage(*headless);
}

// The viewer's passes, in any batching, accumulate exactly what the headless render does.
TEST(ViewerSession, BatchedPassesEqualTheHeadlessRender) {
    const Scene scene = test::readSourceScene("scenes/scene1_area.scene");
    ViewerSession session(scene, createCpuBackend(2), 7, 24, 16);
    for (uint32_t batch : {1u, 2u, 5u, 3u}) session.renderPasses(batch);
    ASSERT_EQ(session.accumulation().passes(), 11u);
    const std::vector<Vec3> viewer = session.image();

    const std::vector<Vec3> reference = headlessImage(scene, 24, 16, 7, StrataBlocks::ones(), 11);
    ASSERT_EQ(viewer.size(), reference.size());
    EXPECT_EQ(std::memcmp(viewer.data(), reference.data(), viewer.size() * sizeof(Vec3)), 0);
}

// Fixed blocks other than one stratum (--blocks B, no growth) still accumulate exactly what --render does.
TEST(ViewerSession, FixedBlocksEqualTheHeadlessRender) {
    const Scene scene = test::readSourceScene("scenes/scene1_area.scene");
    ViewerSession session(scene, createCpuBackend(2), 5, 24, 16);
    const StrataBlocks blocks{1, 10, 1, 1};
    session.setBlocks(blocks, 0.0);
    for (uint32_t batch : {3u, 4u}) session.renderPasses(batch);
    const std::vector<Vec3> viewer = session.image();
    const std::vector<Vec3> reference = headlessImage(scene, 24, 16, 5, blocks, 7);
    ASSERT_EQ(viewer.size(), reference.size());
    EXPECT_EQ(std::memcmp(viewer.data(), reference.data(), viewer.size() * sizeof(Vec3)), 0);
    EXPECT_EQ(session.accumulation().samples(), 7.0);
}

// With growth on, blocks double at cycle boundaries up to the headless render's, each segment's samples
// weighted by the one-stratum passes they stand for; the image stays an unbiased estimate: its mean
// difference from a converged reference (another seed) is within 4 standard errors of 0.
TEST(ViewerSession, BlocksGrowAtCycleBoundariesAndKeepTheEstimate) {
    const Scene scene = test::readSourceScene("scenes/scene1_area.scene");
    ViewerSession session(scene, createCpuBackend(2), 3, 24, 16);
    session.setBlocks(StrataBlocks::ones(), 1e9);  // any pass fits
    const StrataBlocks target = headlessBlocks(flatten(scene).arrays);
    double weightBefore = 0;
    for (int batch = 0; batch < 20 && !(session.accumulation().blocks() == target); ++batch) {
        EXPECT_GT(session.accumulation().blocksWeight(), weightBefore);
        weightBefore = session.accumulation().blocksWeight();
        session.renderPasses(1000);  // stops at the segment's cycle end
    }
    ASSERT_EQ(session.accumulation().blocks(), target) << describeBlocks(session.accumulation().blocks());
    session.renderPasses(1000);  // one whole-light pass: a cycle of the last segment
    // Every segment is whole cycles, each worth one cycle of one stratum per pass (100 passes' worth).
    EXPECT_EQ(std::fmod(session.accumulation().samples(), 100.0), 0.0) << session.accumulation().samples();
    // Light blocks 1, 2, 4, 5, 10, 25, 50, 100 (targets doubling, divisors of 100): one cycle each.
    EXPECT_EQ(session.accumulation().passes(), 100u + 50 + 25 + 20 + 10 + 4 + 2 + 1);
    EXPECT_EQ(session.accumulation().samples(), 800.0);
    const std::vector<Vec3> image = session.image();

    const std::vector<Vec3> reference = headlessImage(scene, 24, 16, 99, StrataBlocks::whole(), 16);
    double mean = 0, sq = 0;
    for (size_t i = 0; i < image.size(); ++i) mean += (image[i].x - reference[i].x) / image.size();
    for (size_t i = 0; i < image.size(); ++i) sq += std::pow(image[i].x - reference[i].x - mean, 2);
    const double se = std::sqrt(sq / (image.size() - 1) / image.size());
    EXPECT_LT(std::abs(mean), 4 * se + 1e-7) << "mean " << mean << " se " << se;
}

// An edit changes the image; undoing it and restarting gives the first image back bit for bit.
TEST(ViewerSession, EditChangesTheImageAndUndoRestoresIt) {
    ViewerSession session(test::readSourceScene("scenes/scene1_area.scene"), createCpuBackend(2), 0, 24, 16);
    session.renderPasses(4);
    const std::vector<Vec3> before = session.image();
    const Vec3 white = session.scene().materials[0].diffuseColor;
    session.scene().materials[0].diffuseColor = Vec3(0.1f, 0.1f, 0.9f);
    session.markDirty(kDirtyScene);
    session.renderPasses(4);
    const std::vector<Vec3> edited = session.image();
    EXPECT_NE(std::memcmp(before.data(), edited.data(), before.size() * sizeof(Vec3)), 0);
    session.scene().materials[0].diffuseColor = white;
    session.markDirty(kDirtyScene);
    session.renderPasses(4);
    const std::vector<Vec3> undone = session.image();
    EXPECT_EQ(std::memcmp(before.data(), undone.data(), before.size() * sizeof(Vec3)), 0);
}

}  // namespace
}  // namespace trazo
