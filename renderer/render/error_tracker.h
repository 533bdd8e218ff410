// The error of a progressive render as it runs, with one owner for the headless render (renderProgressive)
// and the viewer (ProgressiveAccumulation): the two halves the passes are split into, the error probe (drawn
// from the first batch's image, rendered beside it, grown before each estimate and after the last pass) and
// the estimate cadence (when the accumulation is read, and whether the target error is reached). The batches
// themselves are PassScheduler's; the tracker sets when a reading is due in it. Host code.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "backends/backend.h"
#include "render/error_estimate.h"
#include "render/error_probe.h"
#include "render/pass_range.h"
#include "render/pass_scheduler.h"

namespace trazo {

// The two halves (AccumPixel::sumB). Passes v = 0, 1, 2, … alternate between the halves in blocks of
// halfBlockPasses(cycle) passes, the largest power of two dividing the scene's full cycle. Every grid is
// walked in N | cycle blocks and pass v takes block v mod N (strata.h), so over any 2·cycle passes from 0
// each half takes every block of every grid equally often (the half block absorbs N's factor 2^a; passes v
// and v + N fall in different halves because N / halfBlock is odd). Both halves are then
// equally stratified, independent estimates and their difference measures the error of the whole
// (error_estimate.h). At other pass counts the halves hold unequal sets of strata and the estimate is rough.
// cyclePasses = 0 (the default), or a cycle that hit kMaxCyclePasses (then not every grid divides it), makes
// no halves and nothing can be estimated. The split only decides which half a sample is added to: the image
// (sum / count) is the same as without it. renderPassRange also sets FrameParams::strataWindow to 2·cycle:
// each window re-draws every grid's order (re-pairing nested grids), and within a window the argument above
// holds unchanged. Both halves of a window share its pairing, so the estimate leaves out the part of the
// error that re-pairing removes over later windows; with one grid (or independent ones) that part is 0.
bool splitsHalves(uint32_t cyclePasses);
uint32_t halfBlockPasses(uint32_t cyclePasses);  // FrameParams::halfBlock; 0 when there are no halves
// Whether passes `range` hold two equally stratified halves, so their error estimate is unbiased: whole
// windows of 2·cyclePasses passes, starting at a window's start.
bool halvesBalanced(uint32_t cyclePasses, PassRange range);

// Adds passes [firstPass, firstPass + count), each to its half of the split for cyclePasses.
void renderPassRange(Backend& backend, const FrameParams& frame, uint32_t firstPass, uint32_t count,
                     uint32_t cyclePasses);

// The render's error now: from the probe when there is one, otherwise from the halves. Leaves the image's
// accumulation in `accum`.
ErrorEstimate estimateRenderError(Backend& backend, const ErrorProbe& probe, std::vector<AccumPixel>& accum);

// What a tracker estimates, and how often.
struct ErrorTracking {
    double targetError = 0.0;  // reached once an estimate's relError <= this (0: none)
    // Estimate from an error probe (the backend must have one), from the first pass on; else from the halves.
    bool probe = false;
    bool noiseless = false;  // every pass is the same image: no probe, and the error is 0 exactly
    // > 0: a reading every this many seconds of rendering, for display. 0: readings only toward the target,
    // each a little past the passes the last one predicts it needs.
    double displayInterval = 0.0;
};

class ErrorTracker {
public:
    explicit ErrorTracker(const ErrorTracking& how = {});

    // A new accumulation of `frame`'s image from pass `firstPass` on, split for `cyclePasses`: forgets the
    // probe and the readings (not the target), restarts `batches` and schedules the first reading in it.
    void restart(const FrameParams& frame, uint32_t cyclePasses, uint32_t firstPass, PassScheduler& batches);
    // The target error (0: none); reached at once when the last estimate already meets it.
    void setTarget(double relError);

    // The image took its next `count` passes (renderPassRange). With a probe: draws it after the first batch
    // (falling back to the halves, and restarting `batches` for them, when it draws nothing) and renders the
    // same passes into it. Before batches.finished, so the batch's time includes the probe's.
    void rendered(Backend& backend, uint32_t count, PassScheduler& batches);
    // After batches.finished: reads the error where `batches` says a reading is due, decides whether the
    // target is reached and schedules the next reading. `renderSeconds`: rendering time so far (for the
    // display cadence). True when it read an available estimate.
    bool estimateIfDue(Backend& backend, PassScheduler& batches, double renderSeconds);
    // After the last batch: grows the probe to the image's draw now, unless the last reading just did.
    void finish(Backend& backend);

    double targetError() const { return target_; }
    bool targetReached() const { return reached_; }
    const ErrorEstimate& estimate() const { return estimate_; }  // the last available one
    double lastRelError() const { return lastRelError_; }       // the last reading's; NaN when none
    uint32_t readings() const { return readings_; }              // accumulation reads made for estimates
    const ErrorProbe& probe() const { return probe_; }
    ErrorProbe takeProbe() { return std::move(probe_); }

private:
    bool estimating() const { return how_.displayInterval > 0.0 || target_ > 0.0; }
    void drawProbe(Backend& backend, uint32_t count, PassScheduler& batches);
    void growRenderedProbe(Backend& backend);  // to the image's draw after passes_ passes
    bool read(Backend& backend, PassScheduler& batches, double renderSeconds);  // true: available

    ErrorTracking how_;
    double target_ = 0.0;
    FrameParams frame_{};
    uint32_t cyclePasses_ = 0, firstPass_ = 0;
    uint32_t passes_ = 0;    // since the restart
    bool probing_ = false;   // a probe is (to be) drawn and rendered
    ErrorProbe probe_;
    uint32_t grownAt_ = 0;   // passes_ when the probe was last drawn or grown from the image
    std::vector<AccumPixel> accum_;  // the image's accumulation, where the backend must copy it

    ErrorEstimate estimate_;
    double lastRelError_ = NAN;
    uint32_t readings_ = 0;
    double lastReadSeconds_ = 0.0;  // renderSeconds at the last display reading
    bool reached_ = false;
};

}  // namespace trazo
