// MultiBackend with CPU backends standing in for devices: each gets a contiguous share of every batch, and the
// image equals one backend's within the merge bound (counts exactly).
#include "render/multi_backend.h"

#include <gtest/gtest.h>

#include "render/progressive_render.h"
#include "seed_accumulation.h"

namespace trazo {
namespace {

// Records the pass ranges it is asked for; its accumulation counts them (one sample of 1 per pass).
class RecordingBackend final : public Backend {
public:
    explicit RecordingBackend(std::vector<PassRange>& calls) : calls_(calls) {}
    std::string name() const override { return "test"; }
    std::string deviceName() const override { return "recorder"; }
    void upload(const SceneArrays&) override {}
    void resize(uint32_t width, uint32_t height) override { accum_.assign((size_t)width * height, AccumPixel{}); }
    void reset() override { accum_.assign(accum_.size(), AccumPixel{}); }
    void renderPasses(const FrameParams&, uint32_t first, uint32_t count) override {
        calls_.push_back(PassRange{first, first + count});
        for (AccumPixel& p : accum_)
            for (uint32_t pass = first; pass < first + count; ++pass) p.add(Vec3(1.0f), pass % 2 == 1, 1.0f);
    }
    void readAccumulation(std::vector<AccumPixel>& out) override { out = accum_; }
    uint64_t raysTraced() const override { return 10; }
    double traceRays(const std::vector<RayQuery>&, RayQueryKind, std::vector<RayAnswer>&) override { return 0.0; }

private:
    std::vector<PassRange>& calls_;
    std::vector<AccumPixel> accum_;
};

TEST(MultiBackend, SplitsEachBatchIntoContiguousSharesInDeviceOrder) {
    EXPECT_EQ(splitPasses(10, 7, 3, 0), (PassRange{10, 13}));
    EXPECT_EQ(splitPasses(10, 7, 3, 1), (PassRange{13, 15}));
    EXPECT_EQ(splitPasses(10, 7, 3, 2), (PassRange{15, 17}));
    EXPECT_EQ(splitPasses(0, 1, 3, 2).count(), 0u);

    std::vector<std::vector<PassRange>> calls(3);
    std::vector<std::unique_ptr<Backend>> backends;
    for (auto& c : calls) backends.push_back(std::make_unique<RecordingBackend>(c));
    MultiBackend multi(std::move(backends));
    multi.resize(2, 2);
    multi.renderPasses(FrameParams{}, 5, 8);
    multi.renderPasses(FrameParams{}, 13, 1);  // fewer passes than devices: the others sit this batch out
    EXPECT_EQ(calls[0], (std::vector<PassRange>{{5, 8}, {13, 14}}));
    EXPECT_EQ(calls[1], (std::vector<PassRange>{{8, 11}}));
    EXPECT_EQ(calls[2], (std::vector<PassRange>{{11, 13}}));
    std::vector<AccumPixel> accum;
    multi.readAccumulation(accum);
    ASSERT_EQ(accum.size(), 4u);
    EXPECT_EQ(accum[3].count, 9.0);
    EXPECT_EQ(accum[3].countB, 5.0);  // the odd passes of 5..13
    EXPECT_EQ(multi.raysTraced(), 30u);
    EXPECT_EQ(multi.deviceName(), "3 devices: recorder, recorder, recorder");
}

TEST(MultiBackend, TwoOrThreeCpuBackendsEqualOneWithinTheMergeBound) {
    constexpr uint32_t kPasses = 24;
    std::unique_ptr<Backend> one = createCpuBackend(2);
    const std::vector<AccumPixel> single =
        test::renderSeedAccumulation(*one, "scene1_area.scene", 64, 48, {{0, kPasses}});
    for (const size_t devices : {2u, 3u}) {
        std::vector<std::unique_ptr<Backend>> backends;
        for (size_t i = 0; i < devices; ++i) backends.push_back(createCpuBackend(1));
        MultiBackend multi(std::move(backends));
        // In batches, as renderProgressive gives them: each device then holds several ranges.
        const std::vector<AccumPixel> merged =
            test::renderSeedAccumulation(multi, "scene1_area.scene", 64, 48, {{0, 5}, {5, 6}, {6, kPasses}});
        const test::MergeComparison c = test::expectWithinMergeBound(merged, single, kPasses);
        std::printf("[ multi ] %zu backends: %zu of %zu pixels identical in every double\n", devices,
                    c.identicalPixels, c.pixels);
    }
}

// A grown probe's accumulation written back (growRenderedProbe) reads back the same from one CPU backend and
// from several, whose probes are read as their sum; a wrong count is refused.
TEST(MultiBackend, WrittenProbeReadsBackAsWritten) {
    std::vector<AccumPixel> written(3);
    for (size_t k = 0; k < written.size(); ++k) written[k].add(Vec3(0.25f * k, 1.5f, 3.0f), k == 1, 2.0f);
    std::vector<std::unique_ptr<Backend>> backends;
    for (int i = 0; i < 3; ++i) backends.push_back(createCpuBackend(1));
    MultiBackend multi(std::move(backends));
    std::unique_ptr<Backend> single = createCpuBackend(1);
    for (Backend* backend : {static_cast<Backend*>(&multi), single.get()}) {
        backend->resize(8, 4);
        backend->resizeProbe({1u, 9u, 30u});
        backend->writeProbe(written);
        std::vector<AccumPixel> read;
        backend->readProbe(read);
        ASSERT_EQ(read.size(), written.size());
        for (size_t k = 0; k < read.size(); ++k) {
            EXPECT_EQ(read[k].count, written[k].count);
            EXPECT_EQ(read[k].countB, written[k].countB);
            for (int c = 0; c < 3; ++c) EXPECT_EQ(read[k].sum[c], written[k].sum[c]);
            for (int c = 0; c < 3; ++c) EXPECT_EQ(read[k].sumB[c], written[k].sumB[c]);
        }
        EXPECT_THROW(backend->writeProbe(std::vector<AccumPixel>(2)), std::logic_error);
    }
}

}  // namespace
}  // namespace trazo
