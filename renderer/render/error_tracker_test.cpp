// ErrorTracker on a backend whose "render" draws known random values (fake_backend.h): readings come where
// PassScheduler says and nowhere else, the probe is drawn once and grown once before each reading and once
// after the last pass, and the target error stops a render at the pass count it always has.
#include "render/error_tracker.h"

#include <gtest/gtest.h>

#include "render/fake_backend.h"
#include "render/progressive_render.h"

namespace trazo {
namespace {

using test::FakeBackend;

constexpr uint32_t kWidth = 40, kHeight = 30;

FrameParams frameOf(uint32_t width, uint32_t height) {
    FrameParams frame{};
    frame.camera.width = width;
    frame.camera.height = height;
    return frame;
}

// Runs batches of at most `batchPasses` (at a made-up pace of 1 ms a pass) through the tracker as
// renderProgressive does, for `batchCount` batches or until the target is reached; the pass counts where
// it read the error.
struct BatchRun {
    std::vector<uint32_t> readAt;
    uint32_t passes = 0;
    uint32_t batches = 0;
};

BatchRun runBatches(Backend& backend, const FrameParams& frame, uint32_t cycle, ErrorTracker& tracker,
               PassScheduler& batches, uint32_t batchPasses, uint32_t batchCount, double secondsPerBatch = 0.0) {
    BatchRun run;
    double seconds = 0.0;
    for (; run.batches < batchCount && !tracker.targetReached(); ++run.batches) {
        const uint32_t count = batches.upToEstimate(batchPasses);
        renderPassRange(backend, frame, run.passes, count, cycle);
        tracker.rendered(backend, count, batches);
        run.passes += count;
        batches.finished(count, 0.001 * count);
        seconds += secondsPerBatch;
        const uint64_t due = batches.nextEstimate();
        const uint32_t before = tracker.readings();
        tracker.estimateIfDue(backend, batches, seconds);
        if (tracker.readings() == before) {
            if (!tracker.targetReached()) {
                EXPECT_LT(run.passes, due) << "a reading was due and not made";
            }
            continue;
        }
        EXPECT_EQ(tracker.readings(), before + 1);
        // Scheduled before, or (the display cadence) on the spot once the interval has passed.
        if (due != PassScheduler::kNever) {
            EXPECT_EQ(run.passes, due) << "read where no reading was due";
        } else {
            EXPECT_GT(secondsPerBatch, 0.0);
        }
        run.readAt.push_back(run.passes);
    }
    return run;
}

TEST(ErrorTracker, ReadsTheHalvesOnlyWhereTheSchedulerSaysAndEveryTimeItDoes) {
    constexpr uint32_t kCycle = 3;
    FakeBackend backend(500, kCycle, 0.5f);
    PassScheduler batches;
    ErrorTracker tracker(ErrorTracking{.targetError = 1e-6});
    tracker.restart(FrameParams{}, kCycle, 0, batches);
    const BatchRun run = runBatches(backend, FrameParams{}, kCycle, tracker, batches, 5, 25);
    // The first at the first whole window of 2·cycle passes, then at most twice the passes so far (the target
    // is far): never every batch.
    EXPECT_EQ(run.readAt, (std::vector<uint32_t>{6, 12, 24, 48, 96}));
    EXPECT_EQ(run.batches, 25u);
    EXPECT_EQ(backend.reads, 5);  // one accumulation read per reading, none between
    EXPECT_FALSE(tracker.targetReached());
    EXPECT_TRUE(tracker.estimate().available);
    EXPECT_EQ(tracker.estimate().passes, 96u);
    EXPECT_EQ(tracker.lastRelError(), tracker.estimate().relError);
}

TEST(ErrorTracker, WithoutATargetOrADisplayItNeverReads) {
    FakeBackend backend(500, 3, 0.5f);
    PassScheduler batches;
    ErrorTracker tracker;
    tracker.restart(FrameParams{}, 3, 0, batches);
    const BatchRun run = runBatches(backend, FrameParams{}, 3, tracker, batches, 5, 20);
    EXPECT_TRUE(run.readAt.empty());
    EXPECT_EQ(backend.reads, 0);
    EXPECT_TRUE(std::isnan(tracker.lastRelError()));
    EXPECT_FALSE(batches.estimateScheduled());
}

// The viewer's cadence: a reading at the first unbiased pass count once kInterval seconds have passed since
// the last, none scheduled in between; a target met stops, and setTarget judges the last estimate at once.
TEST(ErrorTracker, DisplayCadenceReadsEveryIntervalAtUnbiasedCounts) {
    constexpr uint32_t kCycle = 2;
    constexpr double kInterval = 1.0;
    FakeBackend backend(500, kCycle, 0.5f);
    PassScheduler batches;
    ErrorTracker tracker(ErrorTracking{.displayInterval = kInterval});
    tracker.restart(FrameParams{}, kCycle, 0, batches);
    // 0.3 s and 3 passes a batch: readings at 4 (first unbiased), then the first multiple of 4 after 1 s more.
    const BatchRun run = runBatches(backend, FrameParams{}, kCycle, tracker, batches, 3, 12, 0.3);
    EXPECT_EQ(run.readAt, (std::vector<uint32_t>{4, 16, 28}));
    EXPECT_EQ(backend.reads, 3);
    EXPECT_FALSE(tracker.targetReached());

    ASSERT_TRUE(tracker.estimate().available);
    tracker.setTarget(tracker.estimate().relError * 1.01);
    EXPECT_TRUE(tracker.targetReached());
    tracker.setTarget(tracker.estimate().relError * 0.99);
    EXPECT_FALSE(tracker.targetReached());
    tracker.restart(FrameParams{}, kCycle, 0, batches);  // keeps the target, forgets the estimate
    EXPECT_GT(tracker.targetError(), 0.0);
    EXPECT_FALSE(tracker.estimate().available);
}

// With a probe, every reading is preceded by exactly one growth (one accumulation read besides the reading's
// own), and finish() grows it once more only when passes came after the last reading.
TEST(ErrorTracker, GrowsTheProbeOnceBeforeEachReadingAndOnceAfterTheLastPass) {
    const FrameParams frame = frameOf(kWidth, kHeight);
    FakeBackend backend(kWidth * kHeight, 4, 0.5f, true);
    PassScheduler batches;
    ErrorTracker tracker(ErrorTracking{.targetError = 1e-6, .probe = true});
    tracker.restart(frame, 4, 0, batches);
    const BatchRun run = runBatches(backend, frame, 4, tracker, batches, 3, 6);
    EXPECT_EQ(run.readAt, (std::vector<uint32_t>{1, 2, 4, 8}));  // from the first pass: any count is unbiased
    ASSERT_FALSE(tracker.probe().empty());
    EXPECT_EQ(backend.reads, 1 + 2 * 4);  // the draw, then a growth and a reading each
    ASSERT_GT(run.passes, run.readAt.back());

    tracker.finish(backend);
    EXPECT_EQ(backend.reads, 1 + 2 * 4 + 1) << "grown once after the last pass";
    tracker.finish(backend);
    EXPECT_EQ(backend.reads, 1 + 2 * 4 + 1) << "and only once";

    // The probe is the image's draw now, and holds the image's passes at every pixel.
    std::vector<AccumPixel> image, probeAccum;
    backend.readAccumulation(image);
    backend.readProbe(probeAccum);
    ErrorProbe probe = tracker.probe();
    EXPECT_TRUE(growProbe(image, kWidth, kHeight, frame.seed, probe).empty());
    ASSERT_EQ(probeAccum.size(), tracker.probe().pixels.size());
    for (const AccumPixel& p : probeAccum) ASSERT_EQ(p.count, double(run.passes));
}

TEST(ErrorTracker, AProbeThatDrawsNothingFallsBackToTheHalves) {
    constexpr uint32_t kCycle = 3;
    FakeBackend backend(500, kCycle, 0.5f, true);
    PassScheduler batches;
    ErrorTracker tracker(ErrorTracking{.targetError = 1e-6, .probe = true});
    tracker.restart(FrameParams{}, kCycle, 0, batches);  // a 0 × 0 frame: designProbe draws nothing
    const BatchRun run = runBatches(backend, FrameParams{}, kCycle, tracker, batches, 5, 12);
    EXPECT_TRUE(tracker.probe().empty());
    EXPECT_EQ(backend.probeCalls, 0);
    EXPECT_EQ(run.readAt, (std::vector<uint32_t>{6, 12, 24, 48}));
}

// renderProgressive's stops, for fixed inputs: where the target error stopped it before the tracker owned the
// cadence (the readings land on the scheduler's pass counts whatever the batches' timing, so these are exact).
TEST(ErrorTracker, TargetStopsRenderProgressiveAtTheSamePassCount) {
    struct Case {
        uint32_t pixels, width, height;
        bool probe;
        double target;
        uint32_t cap, passes, checks;
        bool reached;
    };
    const Case cases[] = {
        {4000, 0, 0, false, 0.01, kMaxProgressivePasses, 2712, 8, true},
        {4000, 0, 0, false, 0.02, kMaxProgressivePasses, 672, 6, true},
        {4000, 0, 0, false, 0.01, 48, 48, 2, false},
        {kWidth * kHeight, kWidth, kHeight, true, 0.01, kMaxProgressivePasses, 2244, 13, true},
        {kWidth * kHeight, kWidth, kHeight, true, 0.02, kMaxProgressivePasses, 705, 11, true},
    };
    for (const Case& c : cases) {
        FakeBackend backend(c.pixels, 12, 0.5f, c.probe);
        RenderLimits limits;
        limits.passes = c.cap;
        limits.cyclePasses = 12;
        limits.targetError = c.target;
        limits.errorProbe = c.probe;
        const RenderOutcome out = renderProgressive(backend, frameOf(c.width, c.height), limits);
        EXPECT_EQ(out.passes, c.passes) << c.target << (c.probe ? " with a probe" : "");
        EXPECT_EQ(out.errorChecks, c.checks) << c.target;
        EXPECT_EQ(out.reachedTarget, c.reached) << c.target;
        if (c.reached) {
            EXPECT_LE(out.estimatedRelError, c.target);
        }
        EXPECT_EQ(out.probe.empty(), !c.probe);
    }
}

TEST(ErrorTracker, NoiselessMeetsAnyTargetAfterTheFirstBatchWithoutReading) {
    FakeBackend backend(100, 4, 0.5f, true);
    PassScheduler batches;
    ErrorTracker tracker(ErrorTracking{.targetError = 1e-9, .probe = true, .noiseless = true});
    tracker.restart(frameOf(10, 10), 4, 0, batches);
    const BatchRun run = runBatches(backend, frameOf(10, 10), 4, tracker, batches, 3, 5);
    EXPECT_EQ(run.batches, 1u);
    EXPECT_TRUE(tracker.targetReached());
    EXPECT_EQ(tracker.lastRelError(), 0.0);
    EXPECT_EQ(tracker.readings(), 0u);
    EXPECT_EQ(backend.reads, 0);
    EXPECT_TRUE(tracker.probe().empty());
}

}  // namespace
}  // namespace trazo
