// PassScheduler: the batches of a progressive render, for the headless render (renderProgressive) and the
// viewer (ViewerSession) alike; what differs between them is the time a batch aims at. The first batch after a
// restart is one pass (the first image as soon as a pass allows); later ones take as many passes as fit the
// budget at the last batch's pace. A batch ends early where the error is due to be read (ErrorTracker schedules
// the readings), at a pass count where the estimate is unbiased: any count with an error probe, whole windows
// of 2·cycle passes with the two halves (error_tracker.h). Host code.
#pragma once

#include <algorithm>
#include <cstdint>

namespace trazo {

class PassScheduler {
public:
    static constexpr uint32_t kMaxBatchPasses = 65536;  // a batch of cheap passes still returns now and then

    // A new accumulation: passes count from 0, the pace is unknown, nothing is due. The error can be read
    // after any pass with a probe, at multiples of 2·cyclePasses where the halves split (splitsHalves), else
    // never.
    void restart(uint32_t cyclePasses, bool probed = false);
    // A new segment of the same accumulation (the viewer's grown blocks): passes count from 0 again, with its
    // own cycle, each pass expected to cost `costScale` times the last measured one until measured. A reading
    // that was due stays due, at the new segment's first unbiased pass count.
    void startSegment(uint32_t cyclePasses, double costScale);

    // Passes that take about `seconds` at the last batch's pace, from 1 to kMaxBatchPasses (1 before a batch).
    uint32_t passesFor(double seconds) const;
    // The next batch: passesFor(seconds), at most `cap`, ending where a due reading can be made.
    uint32_t nextBatch(double seconds, uint32_t cap) const { return upToEstimate(std::min(passesFor(seconds), cap)); }
    // At most `count` passes, ending where a due reading can be made.
    uint32_t upToEstimate(uint32_t count) const;
    // A batch of `passes` passes took `seconds` (the pace of the next batches).
    void finished(uint32_t passes, double seconds);
    uint32_t passes() const { return passes_; }                  // since the restart or segment start
    double secondsPerPass() const { return secondsPerPass_; }    // of the last batch; 0 before one

    // Error readings. canEstimate: a probe or halves. estimateSoon: a reading is due at the first pass count
    // from here where it is unbiased. estimateWhenPredicted: after a reading of `relError`, the next is due
    // a little past the passes predicted to reach `target` (error ∝ passes^-1/2), at most twice the passes so
    // far, so the readings stay a small share of the time and the stop lands near the target.
    bool canEstimate() const { return step_ > 0; }
    void estimateSoon();
    void estimateWhenPredicted(double relError, double target);
    bool estimateDue() const { return passes_ >= nextEstimate_; }  // now: read it, then schedule the next
    void estimateDone() { nextEstimate_ = kNever; }                  // read, and none scheduled
    bool estimateScheduled() const { return nextEstimate_ != kNever; }
    uint64_t nextEstimate() const { return nextEstimate_; }  // the pass count it is due at (kNever: none)
    static constexpr uint64_t kNever = UINT64_MAX;

private:
    uint64_t unbiasedFrom(uint64_t passes) const;  // the first pass count ≥ passes where a reading is unbiased

    uint32_t step_ = 0;  // readings are unbiased at multiples of step_ (0: never)
    uint32_t passes_ = 0;
    double secondsPerPass_ = 0.0;
    uint64_t nextEstimate_ = kNever;
};

}  // namespace trazo
