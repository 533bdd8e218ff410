// Batches from PassScheduler, each aiming at kBatchSeconds (often enough for the progress line and the time
// limit). With a target error the accumulation is read where the scheduler says a reading is due.
#include "render/progressive_render.h"

#include <algorithm>
#include <chrono>

#include "render/error_probe.h"
#include "render/pass_scheduler.h"

namespace trazo {

namespace {

constexpr double kBatchSeconds = 0.2;

// The backend's accumulation: in place where it is host memory, else copied into `copy`.
const std::vector<AccumPixel>& accumulationOf(Backend& backend, std::vector<AccumPixel>& copy) {
    if (const std::vector<AccumPixel>* inPlace = backend.hostAccumulation()) return *inPlace;
    backend.readAccumulation(copy);
    return copy;
}

}  // namespace

void growRenderedProbe(Backend& backend, const FrameParams& frame, const RenderLimits& limits, uint32_t passes,
                       ErrorProbe& probe, std::vector<AccumPixel>& accum) {
    if (probe.empty() || passes == 0) return;
    const ErrorProbe added =
        growProbe(accumulationOf(backend, accum), frame.camera.width, frame.camera.height, frame.seed, probe);
    if (added.empty()) return;
    std::vector<AccumPixel> probeAccum, addedAccum;
    backend.readProbe(probeAccum);
    backend.resizeProbe(added.pixels);
    renderPassRange(backend, probeFrame(frame), limits.firstPass, passes, limits.cyclePasses);
    backend.readProbe(addedAccum);
    addToProbe(probe, probeAccum, added, addedAccum);
    backend.resizeProbe(probe.pixels);
    backend.writeProbe(probeAccum);
}

bool splitsHalves(uint32_t cyclePasses) { return cyclePasses > 0 && cyclePasses < kMaxCyclePasses; }

bool halvesBalanced(uint32_t cyclePasses, PassRange range) {
    const uint64_t window = 2ull * cyclePasses;
    return splitsHalves(cyclePasses) && range.first % window == 0 && range.count() % window == 0;
}

uint32_t halfBlockPasses(uint32_t cyclePasses) {
    return splitsHalves(cyclePasses) ? cyclePasses & (~cyclePasses + 1u) : 0u;  // lowest set bit
}

void renderPassRange(Backend& backend, const FrameParams& frame, uint32_t firstPass, uint32_t count,
                     uint32_t cyclePasses) {
    FrameParams split = frame;
    split.halfBlock = halfBlockPasses(cyclePasses);
    // Two cycles per window: the halves stay equally stratified within each (see progressive_render.h).
    split.strataWindow = splitsHalves(cyclePasses) ? 2 * cyclePasses : 0u;
    backend.renderPasses(split, firstPass, count);
}

ErrorEstimate estimateRenderError(Backend& backend, const ErrorProbe& probe, std::vector<AccumPixel>& accum) {
    backend.readAccumulation(accum);
    if (probe.empty()) return estimateError(accum);
    std::vector<AccumPixel> probeAccum;
    backend.readProbe(probeAccum);
    return estimateErrorWithProbe(accum, probe, probeAccum);
}

ErrorEstimate estimateRenderError(Backend& backend, const RenderLimits& limits, const ErrorProbe& probe,
                                  std::vector<AccumPixel>& accum) {
    ErrorEstimate e = estimateRenderError(backend, probe, accum);
    if (limits.noiseless && !accum.empty()) {
        e.available = e.exact = true;
        e.rmse = e.relError = 0.0;
    }
    return e;
}

RenderOutcome renderProgressive(Backend& backend, const FrameParams& frame, const RenderLimits& limits,
                                const std::function<void(const RenderProgress&)>& onProgress) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

    const uint32_t maxPasses = std::min(limits.passes, kMaxProgressivePasses);
    const FrameParams probe = probeFrame(frame);
    PassScheduler batches;
    batches.restart(limits.cyclePasses, limits.errorProbe);
    const bool targeted = limits.targetError > 0.0 && batches.canEstimate();
    if (targeted) batches.estimateSoon();
    std::vector<AccumPixel> accum;

    RenderOutcome out;
    bool probed = limits.errorProbe && !limits.noiseless;
    auto stopped = [&] { return limits.stop && limits.stop->load(); };
    double batchSeconds = kBatchSeconds;
    uint32_t grownAt = 0;  // the passes when the probe was last grown (or drawn) from the image
    while (out.passes < maxPasses && !stopped()) {
        const double batchStart = elapsed();
        const uint32_t count = batches.nextBatch(batchSeconds, maxPasses - out.passes);
        renderPassRange(backend, frame, limits.firstPass + out.passes, count, limits.cyclePasses);
        if (probed && out.probe.empty()) {  // drawn from the first batch's image, independent of its own passes
            out.probe = designProbe(accumulationOf(backend, accum), frame.camera.width, frame.camera.height, frame.seed);
            if (out.probe.empty()) {  // nothing drawn (a 1-pixel image, by chance): the halves
                probed = false;
                batches.restart(limits.cyclePasses, false);
                if (targeted) batches.estimateSoon();
            } else {
                backend.resizeProbe(out.probe.pixels);
                grownAt = out.passes + count;
            }
        }
        if (probed) renderPassRange(backend, probe, limits.firstPass + out.passes, count, limits.cyclePasses);
        out.passes += count;
        batches.finished(count, elapsed() - batchStart);
        const double t = elapsed();

        if (limits.noiseless && limits.targetError > 0.0) {  // the error is 0 from the first pass
            out.estimatedRelError = 0.0;
            out.reachedTarget = true;
            if (onProgress) onProgress(RenderProgress{out.passes, out.passes, t});
            break;
        }
        if (targeted && batches.estimateDue()) {
            if (probed) growRenderedProbe(backend, frame, limits, out.passes, out.probe, accum);
            grownAt = out.passes;
            const ErrorEstimate e = estimateRenderError(backend, out.probe, accum);
            out.estimatedRelError = e.relError;
            ++out.errorChecks;
            if (e.available && e.relError <= limits.targetError) {
                out.reachedTarget = true;
                if (onProgress) onProgress(RenderProgress{out.passes, out.passes, t});
                break;
            }
            batches.estimateWhenPredicted(e.available ? e.relError : 0.0, limits.targetError);
        }
        const uint32_t aim = (uint32_t)std::min<uint64_t>(batches.nextEstimate(), maxPasses);
        if (onProgress) onProgress(RenderProgress{out.passes, aim, t});

        if (limits.seconds > 0.0) {
            const double left = limits.seconds - t;
            if (left < 0.5 * batches.secondsPerPass()) break;  // one more pass would overshoot more than it helps
            batchSeconds = std::min(kBatchSeconds, left);
        }
    }
    if (probed && grownAt != out.passes) growRenderedProbe(backend, frame, limits, out.passes, out.probe, accum);
    out.seconds = elapsed();
    out.rays = backend.raysTraced();
    return out;
}

}  // namespace trazo
