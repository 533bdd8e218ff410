// A straight loop: PassScheduler sizes each batch to aim at kBatchSeconds (often enough for the progress line
// and the time limit), the batch is rendered, and the ErrorTracker renders its probe, reads the error where
// a reading is due and says whether the target is reached.
#include "render/progressive_render.h"

#include <algorithm>
#include <chrono>

#include "render/pass_scheduler.h"

namespace trazo {

namespace {

constexpr double kBatchSeconds = 0.2;

ErrorTracking trackingOf(const RenderLimits& limits) {
    return ErrorTracking{limits.targetError, limits.errorProbe, limits.noiseless, 0.0};
}

// With a time limit: false once one more pass would overshoot it more than it helps; else the next batch's
// aim, at most what is left.
bool timeLeft(const RenderLimits& limits, const PassScheduler& batches, double t, double& batchSeconds) {
    if (limits.seconds <= 0.0) return true;
    const double left = limits.seconds - t;
    if (left < 0.5 * batches.secondsPerPass()) return false;
    batchSeconds = std::min(kBatchSeconds, left);
    return true;
}

}  // namespace

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
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    const uint32_t maxPasses = std::min(limits.passes, kMaxProgressivePasses);
    PassScheduler batches;
    ErrorTracker tracker(trackingOf(limits));
    tracker.restart(frame, limits.cyclePasses, limits.firstPass, batches);
    RenderOutcome out;
    double batchSeconds = kBatchSeconds;
    while (out.passes < maxPasses && !(limits.stop && limits.stop->load())) {
        const double batchStart = elapsed();
        const uint32_t count = batches.nextBatch(batchSeconds, maxPasses - out.passes);
        renderPassRange(backend, frame, limits.firstPass + out.passes, count, limits.cyclePasses);
        tracker.rendered(backend, count, batches);
        out.passes += count;
        batches.finished(count, elapsed() - batchStart);
        const double t = elapsed();
        tracker.estimateIfDue(backend, batches, t);
        const bool reached = tracker.targetReached();
        const uint32_t aim = reached ? out.passes : (uint32_t)std::min<uint64_t>(batches.nextEstimate(), maxPasses);
        if (onProgress) onProgress(RenderProgress{out.passes, aim, t});
        if (reached || !timeLeft(limits, batches, t, batchSeconds)) break;
    }
    tracker.finish(backend);
    out.seconds = elapsed();
    out.rays = backend.raysTraced();
    out.estimatedRelError = tracker.lastRelError();
    out.errorChecks = tracker.readings();
    out.reachedTarget = tracker.targetReached();
    out.probe = tracker.takeProbe();
    return out;
}

}  // namespace trazo
