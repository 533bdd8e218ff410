// renderProgressive(): runs passes on a backend until a pass count, a time budget or a target error is
// reached, in batches sized so progress reports (and the time limit) stay responsive; its ErrorTracker
// (error_tracker.h) owns the halves, the probe and the estimates. Host code.
#pragma once

#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>

#include "backends/backend.h"
#include "render/error_estimate.h"
#include "render/error_probe.h"
#include "render/error_tracker.h"
#include "render/pass_range.h"
#include "render/strata_plan.h"

namespace trazo {

constexpr uint32_t kMaxProgressivePasses = 1u << 30;

struct RenderLimits {
    uint32_t passes = 1;       // stop after this many passes (capped at kMaxProgressivePasses)
    double seconds = 0.0;      // and after this wall time, when > 0 (whichever comes first)
    double targetError = 0.0;  // and once estimateRenderError(...).relError <= this, when > 0
    // The scene's full cycle for the frame's blocks (fullCyclePasses): sets the half split; without a probe
    // the target error is checked only at multiples of 2·cyclePasses, where the halves' estimate is unbiased
    // (and a stratified image is at its best). 0: no halves, and no target error without a probe.
    uint32_t cyclePasses = 0;
    uint32_t firstPass = 0;  // the global index of the first pass (a partial render of passes [first, first + passes))
    // Estimate the error with a probe (render/error_probe.h; the backend must have one): drawn after the first
    // pass, then rendered beside the image in every batch and grown before each estimate; the target error is
    // checked from the first pass.
    bool errorProbe = false;
    // Every pass is the same image (noSamplingNoise): no probe, the error is 0 exactly, and a target error is met
    // by the first pass.
    bool noiseless = false;
    // When set and true (a signal handler sets it), the render stops after the current batch.
    const std::atomic<bool>* stop = nullptr;
};

struct RenderProgress {
    uint32_t passesDone;
    uint32_t passesTarget;  // with a target error: the pass count the render now expects to need
    double elapsedSeconds;
};

struct RenderOutcome {
    uint32_t passes = 0;  // rendered: passes [firstPass, firstPass + passes)
    double seconds = 0.0;
    uint64_t rays = 0;
    double estimatedRelError = NAN;  // at the last target-error check (NaN when none was made)
    uint32_t errorChecks = 0;        // accumulation reads made for the target error
    bool reachedTarget = false;
    ErrorProbe probe;  // with limits.errorProbe: the probe drawn after the first batch, grown after the last
};

// The render's error for a render of limits (estimateRenderError of error_tracker.h): 0 exactly where
// limits.noiseless (ErrorEstimate::exact).
ErrorEstimate estimateRenderError(Backend& backend, const RenderLimits& limits, const ErrorProbe& probe,
                                  std::vector<AccumPixel>& accum);

RenderOutcome renderProgressive(Backend& backend, const FrameParams& frame, const RenderLimits& limits,
                                const std::function<void(const RenderProgress&)>& onProgress = {});

}  // namespace trazo
