#include "render/pass_scheduler.h"

#include <gtest/gtest.h>

#include <cmath>

#include "render/strata_plan.h"

namespace trazo {
namespace {

TEST(PassScheduler, OnePassFirstThenTheBudgetAtTheLastBatchsPace) {
    PassScheduler s;
    s.restart(0);
    EXPECT_EQ(s.nextBatch(0.2, 1000), 1u);  // pace unknown
    s.finished(1, 0.5);
    EXPECT_EQ(s.nextBatch(0.2, 1000), 1u);  // slower than the budget: still one
    s.finished(1, 0.01);
    EXPECT_EQ(s.nextBatch(0.2, 1000), 20u);
    EXPECT_EQ(s.nextBatch(0.2, 7), 7u);
    s.finished(20, 0.02);  // the last batch's pace, not the average
    EXPECT_EQ(s.nextBatch(0.2, 1000), 200u);
    EXPECT_EQ(s.passes(), 22u);
    s.finished(1, 1e-12);
    EXPECT_EQ(s.nextBatch(INFINITY, UINT32_MAX), PassScheduler::kMaxBatchPasses);
    s.restart(0);
    EXPECT_EQ(s.passes(), 0u);
    EXPECT_EQ(s.nextBatch(0.2, 1000), 1u);
}

TEST(PassScheduler, WithHalvesReadingsComeAtWholeWindowsOfTwoCycles) {
    PassScheduler s;
    s.restart(3);
    ASSERT_TRUE(s.canEstimate());
    EXPECT_FALSE(s.estimateScheduled());
    s.finished(1, 0.001);
    s.estimateSoon();
    EXPECT_EQ(s.nextEstimate(), 6u);
    EXPECT_EQ(s.nextBatch(1.0, 1000), 5u);  // ends at pass 6
    s.finished(5, 0.005);
    EXPECT_TRUE(s.estimateDue());
    s.estimateDone();
    EXPECT_FALSE(s.estimateDue());
    EXPECT_EQ(s.nextBatch(1.0, 1000), 1000u);
    s.estimateSoon();  // at a window's end already: due now
    EXPECT_TRUE(s.estimateDue());
    // Error 2× the target at 6 passes: 1.05 · 6 · 4 = 25.2 passes predicted, but at most 2 · 6; rounded up to 12.
    s.estimateWhenPredicted(0.1, 0.05);
    EXPECT_EQ(s.nextEstimate(), 12u);
    // Close to the target: 1.05 · 6 · 1.2² = 9.07, rounded up to the window's end, 12; under it: the next pass,
    // rounded up to 12 too.
    s.estimateWhenPredicted(0.06, 0.05);
    EXPECT_EQ(s.nextEstimate(), 12u);
    s.estimateWhenPredicted(0.01, 0.05);
    EXPECT_EQ(s.nextEstimate(), 12u);
    s.estimateWhenPredicted(0.0, 0.05);  // unknown: twice the passes
    EXPECT_EQ(s.nextEstimate(), 12u);
}

TEST(PassScheduler, WithAProbeAnyPassCountAndTheExactPrediction) {
    PassScheduler s;
    s.restart(3, true);
    s.estimateSoon();
    EXPECT_EQ(s.nextEstimate(), 1u);
    s.finished(1, 0.001);
    EXPECT_TRUE(s.estimateDue());
    s.finished(9, 0.009);
    s.estimateWhenPredicted(0.06, 0.05);  // 1.05 · 10 · 1.44 = 15.12
    EXPECT_EQ(s.nextEstimate(), 15u);
    EXPECT_EQ(s.nextBatch(1.0, 1000), 5u);
    s.estimateWhenPredicted(0.01, 0.05);  // below the target already: the next pass
    EXPECT_EQ(s.nextEstimate(), 11u);
}

TEST(PassScheduler, NoHalvesNoReadings) {
    for (uint32_t cycle : {0u, kMaxCyclePasses}) {
        PassScheduler s;
        s.restart(cycle);
        EXPECT_FALSE(s.canEstimate());
        s.estimateSoon();
        EXPECT_FALSE(s.estimateScheduled());
        s.finished(4, 0.004);
        EXPECT_FALSE(s.estimateDue());
        EXPECT_EQ(s.nextBatch(1.0, 1000), 1000u);
    }
}

TEST(PassScheduler, ANewSegmentCountsAfreshAtTheScaledPaceAndKeepsADueReading) {
    PassScheduler s;
    s.restart(2);
    s.finished(2, 0.02);
    s.estimateSoon();  // due at 4
    s.startSegment(5, 2.0);
    EXPECT_EQ(s.passes(), 0u);
    EXPECT_DOUBLE_EQ(s.secondsPerPass(), 0.02);
    EXPECT_EQ(s.nextEstimate(), 10u);
    EXPECT_EQ(s.nextBatch(0.1, 1000), 5u);
    s.estimateDone();
    s.startSegment(5, 2.0);
    EXPECT_FALSE(s.estimateScheduled());
}

}  // namespace
}  // namespace trazo
