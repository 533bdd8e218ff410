// Tests of the viewer's closing-line numbers: first-image times, frames and batches, and the drag frame rate
// (frames of one drag at most 0.5 s apart; the first frame of a drag only starts the clock).
#include "model/viewer_stats.h"

#include <gtest/gtest.h>

namespace trazo {
namespace {

using Clock = ViewerStats::Clock;
using std::chrono::milliseconds;

TEST(ViewerStats, CountsFramesImagesAndBatches) {
    const Clock::time_point t0{};
    ViewerStats stats(t0);
    stats.frameShown(t0, t0 + milliseconds(100), false, false, false);
    stats.frameShown(t0, t0 + milliseconds(250), true, false, false);
    stats.frameShown(t0, t0 + milliseconds(400), true, false, false);  // the first image stays at 0.25 s
    stats.frameShown(t0, t0 + milliseconds(750), true, true, false);
    stats.batchStarted();
    stats.batchStarted();
    EXPECT_EQ(stats.frames(), 4u);
    EXPECT_EQ(stats.summary(t0 + milliseconds(2000)),
              "first image after 0.250 s (full size after 0.750 s); 2.00 s open, 4 frames drawn; while dragging 0.0 "
              "fps (0 frames, 0.0 ms of work each); 2 batches");
}

TEST(ViewerStats, NoImageYetReadsMinusOne) {
    const Clock::time_point t0{};
    const ViewerStats stats(t0);
    EXPECT_EQ(stats.summary(t0 + milliseconds(500)).rfind("first image after -1.000 s (full size after -1.000 s); "
                                                          "0.50 s open, 0 frames drawn",
                                                          0),
              0u);
}

TEST(ViewerStats, DragRateCountsFramesOfOneDrag) {
    const Clock::time_point t0 = Clock::time_point{} + milliseconds(1000);
    ViewerStats stats(t0);
    // Frames every 20 ms with 5 ms of work each; the first only starts the drag's clock.
    for (int i = 0; i < 11; ++i) {
        const Clock::time_point shown = t0 + milliseconds(20 * i);
        stats.frameShown(shown - milliseconds(5), shown, true, true, true);
    }
    // A pause over 0.5 s starts a new drag: its first frame is not counted either.
    stats.frameShown(t0 + milliseconds(1795), t0 + milliseconds(1800), true, true, true);
    stats.frameShown(t0 + milliseconds(2000), t0 + milliseconds(2020), true, true, false);  // not dragging
    EXPECT_EQ(stats.summary(t0 + milliseconds(3000)),
              "first image after 0.000 s (full size after 0.000 s); 3.00 s open, 13 frames drawn; while dragging 50.0 "
              "fps (10 frames, 5.0 ms of work each); 0 batches");
}

TEST(ViewerStats, MoveLatencyRunsFromTheFirstInputToTheImageOfTheBatchAfterIt) {
    const Clock::time_point t0{};
    ViewerStats stats(t0);
    EXPECT_EQ(stats.imageShown(t0 + milliseconds(5)), -1.0);  // no move: nothing measured
    stats.moveInput(t0 + milliseconds(10));
    stats.moveInput(t0 + milliseconds(20));                   // the same image will show both
    EXPECT_EQ(stats.imageShown(t0 + milliseconds(30)), -1.0); // an older batch's image: not the move's
    stats.batchStarted();
    EXPECT_DOUBLE_EQ(stats.imageShown(t0 + milliseconds(70)), 0.060);
    EXPECT_EQ(stats.imageShown(t0 + milliseconds(80)), -1.0); // measured once
    stats.moveInput(t0 + milliseconds(100));
    stats.batchStarted();
    EXPECT_DOUBLE_EQ(stats.imageShown(t0 + milliseconds(120)), 0.020);
    EXPECT_EQ(stats.summary(t0 + milliseconds(1000)),
              "first image after -1.000 s (full size after -1.000 s); 1.00 s open, 0 frames drawn; while dragging 0.0 "
              "fps (0 frames, 0.0 ms of work each); 2 batches; object moves shown after 40.0 ms on average (worst "
              "60.0 ms, 2 images)");
}

}  // namespace
}  // namespace trazo
