// ProgressiveAccumulation: the viewer's image as it converges. Batches of passes run on a worker thread through
// the same renderPassRange() as the headless render, sized by the same PassScheduler; the worker sees only the
// backend and a copy of the frame, so the UI thread may edit the scene meanwhile. Host code, no window.
//
// Blocks of strata (integrator/strata.h) start at one stratum per pass, so the first image after an edit is as
// fast as a pass can be. With growth on, whenever a cycle of the current blocks is complete and a pass at
// twice the blocks would still fit the pass budget, the accumulation goes on in a new segment: blocks
// doubled (up to the headless render's), a seed of its own, and samples weighted by the first segment's
// passes each stands for (FrameParams::sampleWeight). Every segment is whole cycles, an exact stratified
// estimate.
//
// Convergence: the headless render's ErrorTracker, on a display cadence: at the end of a batch whose passes
// complete an even number of cycles of the current segment (where the two halves are equally stratified,
// error_tracker.h), at most every kEstimateInterval seconds of rendering, the error is estimated from the
// halves and added to the series; batches are cut at those points when an estimate is due. While blocks grow,
// segments are single cycles and nothing is estimated; after growth the earlier segments make the estimate
// approximate.
#pragma once

#include <functional>
#include <future>
#include <thread>
#include <vector>

#include "backends/backend.h"
#include "render/error_estimate.h"
#include "render/error_tracker.h"
#include "render/pass_scheduler.h"
#include "scene/scene.h"

namespace trazo {

// One point of the convergence plot: the estimated relative error (error_estimate.h) after `seconds` of
// rendering since the last restart.
struct ConvergencePoint {
    double seconds;
    double relError;
    uint32_t passes;
};

class ProgressiveAccumulation {
public:
    static constexpr double kEstimateInterval = 0.25;

    ~ProgressiveAccumulation();  // waits for a running batch
    // Clears `backend`'s accumulation and starts the first segment of an image of `scene`'s camera at
    // width × height. `arrays` (what the backend holds) must stay alive and unchanged until the next restart.
    void restart(Backend& backend, const Scene& scene, const SceneArrays& arrays, uint32_t width, uint32_t height,
                 uint32_t seed);
    // The blocks each restart begins with, and growth while a pass at twice the blocks takes at most
    // `growthPassSeconds` (0: never). Takes effect at the next restart.
    void setBlocks(const StrataBlocks& first, double growthPassSeconds);
    // Stops batches once an estimate reaches relError <= target (0: never). Kept across restarts.
    void setTargetError(double target);
    void setOnBatchDone(std::function<void()> callback) { onBatchDone_ = std::move(callback); }

    // A batch of at most `count` passes on the worker (none once the target error is reached); it ends early at
    // the segment's cycle end while blocks grow, and where a due estimate is unbiased.
    void start(Backend& backend, uint32_t count);
    // True while a batch runs; collects a finished one (and rethrows its exception).
    bool busy(Backend& backend);
    void waitIdle(Backend& backend);
    // Passes for a batch of about `seconds` (1 right after a restart: the first image fast).
    uint32_t passesFor(double seconds) const { return batches_.passesFor(seconds); }

    uint32_t passes() const { return passes_; }  // since the last restart
    double samples() const { return samples_; }  // passes weighted by their segment's sampleWeight
    double blocksWeight() const { return frame_.sampleWeight; }
    const StrataBlocks& blocks() const { return frame_.blocks; }
    uint32_t cyclePasses() const { return cyclePasses_; }  // of one stratum per pass
    uint64_t rays() const { return rays_; }
    double renderSeconds() const { return renderSeconds_; }
    double secondsPerPixelPass() const { return secondsPerPixelPass_; }  // kept across restarts; 0 before a batch
    uint64_t generation() const { return generation_; }  // changes whenever the accumulation does
    const std::vector<ConvergencePoint>& convergence() const { return convergence_; }
    const ErrorEstimate& errorEstimate() const { return tracker_.estimate(); }
    double targetError() const { return tracker_.targetError(); }
    bool targetReached() const { return tracker_.targetReached(); }

private:
    void startSegment(const StrataBlocks& blocks);  // frame_ for a new segment from the current pass on
    void growBlocks();                              // a larger segment when it pays

    const SceneArrays* arrays_ = nullptr;
    CameraFrame camera_{};
    uint32_t seed_ = 0, width_ = 0, height_ = 0;
    FrameParams frame_{};
    uint32_t cyclePasses_ = 1;
    uint32_t segment_ = 0;        // segments since the last restart
    uint32_t segmentCycle_ = 1;   // fullCyclePasses of its blocks
    PassScheduler batches_;       // counts the current segment's passes
    StrataBlocks firstBlocks_{};  // setBlocks
    double growthPassSeconds_ = 0;

    std::thread worker_;
    std::future<double> batch_;  // seconds the batch took
    uint32_t batchPasses_ = 0;
    std::function<void()> onBatchDone_;

    uint32_t passes_ = 0;
    double samples_ = 0.0;
    uint64_t rays_ = 0;
    double renderSeconds_ = 0.0;
    double secondsPerPixelPass_ = 0.0;
    uint64_t generation_ = 0;

    std::vector<ConvergencePoint> convergence_;
    ErrorTracker tracker_{ErrorTracking{.displayInterval = kEstimateInterval}};  // from the halves
};

}  // namespace trazo
