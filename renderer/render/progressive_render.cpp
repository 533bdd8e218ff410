// Batching of passes: the first batch is one pass; later ones aim at kBatchSeconds each. With a target
// error the accumulation is read at growing intervals (spaced by the predicted need; without a probe at
// multiples of 2·cycle).
#include "render/progressive_render.h"

#include <algorithm>
#include <chrono>

#include "render/error_probe.h"

namespace trazo {

namespace {

constexpr double kBatchSeconds = 0.2;

uint64_t roundUp(uint64_t v, uint64_t step) { return (v + step - 1) / step * step; }

// The backend's accumulation: in place where it is host memory, else copied into `copy`.
const std::vector<AccumPixel>& accumulationOf(Backend& backend, std::vector<AccumPixel>& copy) {
    if (const std::vector<AccumPixel>* inPlace = backend.hostAccumulation()) return *inPlace;
    backend.readAccumulation(copy);
    return copy;
}

}  // namespace

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

RenderOutcome renderProgressive(Backend& backend, const FrameParams& frame, const RenderLimits& limits,
                                const std::function<void(const RenderProgress&)>& onProgress) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

    const uint32_t maxPasses = std::min(limits.passes, kMaxProgressivePasses);
    bool probed = limits.errorProbe;
    const FrameParams probe = probeFrame(frame);
    const bool targeted = limits.targetError > 0.0 && (probed || splitsHalves(limits.cyclePasses));
    // The probe's estimate holds at any pass count; the halves' where they are balanced.
    const uint64_t checkStep = probed ? 1u : 2ull * std::max(limits.cyclePasses, 1u);
    uint64_t nextCheck = targeted ? checkStep : UINT64_MAX;
    std::vector<AccumPixel> accum;

    RenderOutcome out;
    uint32_t batch = 1;
    auto stopped = [&] { return limits.stop && limits.stop->load(); };
    while (out.passes < maxPasses && !stopped()) {
        const uint32_t count =
            (uint32_t)std::min<uint64_t>({batch, maxPasses - out.passes, nextCheck - out.passes});
        renderPassRange(backend, frame, limits.firstPass + out.passes, count, limits.cyclePasses);
        if (probed && out.probe.empty()) {  // drawn from the first batch's image, independent of its own passes
            out.probe = designProbe(accumulationOf(backend, accum), frame.camera.width, frame.camera.height, frame.seed);
            if (out.probe.empty()) probed = false;  // nothing drawn (a 1-pixel image, by chance): the halves
            else backend.resizeProbe(out.probe.pixels);
        }
        if (probed) renderPassRange(backend, probe, limits.firstPass + out.passes, count, limits.cyclePasses);
        out.passes += count;
        const double t = elapsed();

        if (targeted && out.passes >= nextCheck) {
            const ErrorEstimate e = estimateRenderError(backend, out.probe, accum);
            out.estimatedRelError = e.relError;
            ++out.errorChecks;
            if (e.available && e.relError <= limits.targetError) {
                out.reachedTarget = true;
                if (onProgress) onProgress(RenderProgress{out.passes, out.passes, t});
                break;
            }
            // Error ∝ passes^-1/2: aim a little past the predicted need, at most doubling per check, so
            // the reads stay a small share of the time and the stop lands near the target.
            double predicted = 2.0 * out.passes;
            if (e.available && e.relError > 0.0) {
                const double ratio = e.relError / limits.targetError;
                predicted = std::min(predicted, 1.05 * out.passes * ratio * ratio);
            }
            nextCheck = roundUp(std::max<uint64_t>((uint64_t)predicted, out.passes + 1), checkStep);
        }
        const uint32_t aim = targeted ? (uint32_t)std::min<uint64_t>(nextCheck, maxPasses) : maxPasses;
        if (onProgress) onProgress(RenderProgress{out.passes, aim, t});

        const double perPass = t / out.passes;
        double target = kBatchSeconds;
        if (limits.seconds > 0.0) {
            const double left = limits.seconds - t;
            if (left < 0.5 * perPass) break;  // one more pass would overshoot the budget more than it helps
            target = std::min(target, left);
        }
        batch = (uint32_t)std::clamp(target / std::max(perPass, 1e-9), 1.0, 65536.0);
    }
    out.seconds = elapsed();
    out.rays = backend.raysTraced();
    return out;
}

}  // namespace trazo
