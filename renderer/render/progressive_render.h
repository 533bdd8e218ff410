// renderProgressive(): runs passes on a backend until a pass count, a time budget or a target error is
// reached, in batches sized so progress reports (and the time limit) stay responsive. Host code.
#pragma once

#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>

#include "backends/backend.h"
#include "render/error_estimate.h"
#include "render/error_probe.h"
#include "render/pass_range.h"
#include "render/strata_plan.h"

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

// Grows the probe to the image's draw after `passes` passes (growProbe) and renders the pixels it adds over
// passes [limits.firstPass, limits.firstPass + passes) of frame's probe frame, keeping what the others had
// summed. renderProgressive calls it before every estimate it makes and after its last pass. Leaves the
// image's accumulation in `accum` where the backend must copy it.
void growRenderedProbe(Backend& backend, const FrameParams& frame, const RenderLimits& limits, uint32_t passes,
                       ErrorProbe& probe, std::vector<AccumPixel>& accum);

// The render's error now: from the probe when there is one, otherwise from the halves. Leaves the image's
// accumulation in `accum`.
ErrorEstimate estimateRenderError(Backend& backend, const ErrorProbe& probe, std::vector<AccumPixel>& accum);
// The same for a render of limits: 0 exactly where limits.noiseless (ErrorEstimate::exact).
ErrorEstimate estimateRenderError(Backend& backend, const RenderLimits& limits, const ErrorProbe& probe,
                                  std::vector<AccumPixel>& accum);

RenderOutcome renderProgressive(Backend& backend, const FrameParams& frame, const RenderLimits& limits,
                                const std::function<void(const RenderProgress&)>& onProgress = {});

// Adds passes [firstPass, firstPass + count), each to its half of the split for cyclePasses.
void renderPassRange(Backend& backend, const FrameParams& frame, uint32_t firstPass, uint32_t count,
                     uint32_t cyclePasses);

}  // namespace trazo
