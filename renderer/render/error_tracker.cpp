#include "render/error_tracker.h"

#include <algorithm>

#include "render/strata_plan.h"

namespace trazo {

namespace {

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
    // Two cycles per window: the halves stay equally stratified within each (see the header).
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

ErrorTracker::ErrorTracker(const ErrorTracking& how) : how_(how) { setTarget(how.targetError); }

void ErrorTracker::restart(const FrameParams& frame, uint32_t cyclePasses, uint32_t firstPass,
                           PassScheduler& batches) {
    frame_ = frame;
    cyclePasses_ = cyclePasses;
    firstPass_ = firstPass;
    passes_ = 0;
    probing_ = how_.probe && !how_.noiseless;
    probe_ = ErrorProbe{};
    grownAt_ = 0;
    estimate_ = ErrorEstimate{};
    lastRelError_ = NAN;
    readings_ = 0;
    lastReadSeconds_ = 0.0;
    reached_ = false;
    // The scheduler's step follows what was asked for: a noiseless render stops before any reading.
    batches.restart(cyclePasses, how_.probe);
    if (estimating()) batches.estimateSoon();  // the first reading as soon as one is unbiased
}

void ErrorTracker::setTarget(double relError) {
    target_ = std::max(relError, 0.0);
    reached_ = target_ > 0.0 && estimate_.available && estimate_.relError <= target_;
}

void ErrorTracker::rendered(Backend& backend, uint32_t count, PassScheduler& batches) {
    if (probing_ && probe_.empty()) drawProbe(backend, count, batches);
    if (probing_) renderPassRange(backend, probeFrame(frame_), firstPass_ + passes_, count, cyclePasses_);
    passes_ += count;
}

// From the first batch's image, so the draw is independent of the probe's own passes.
void ErrorTracker::drawProbe(Backend& backend, uint32_t count, PassScheduler& batches) {
    probe_ = designProbe(accumulationOf(backend, accum_), frame_.camera.width, frame_.camera.height, frame_.seed);
    if (probe_.empty()) {  // nothing drawn (a 1-pixel image, by chance): the halves
        probing_ = false;
        batches.restart(cyclePasses_, false);
        if (estimating()) batches.estimateSoon();
        return;
    }
    backend.resizeProbe(probe_.pixels);
    grownAt_ = passes_ + count;
}

// Renders the pixels growProbe adds over all the image's passes so far, keeping what the others had summed.
void ErrorTracker::growRenderedProbe(Backend& backend) {
    grownAt_ = passes_;
    if (probe_.empty() || passes_ == 0) return;
    const ErrorProbe added =
        growProbe(accumulationOf(backend, accum_), frame_.camera.width, frame_.camera.height, frame_.seed, probe_);
    if (added.empty()) return;
    std::vector<AccumPixel> probeAccum, addedAccum;
    backend.readProbe(probeAccum);
    backend.resizeProbe(added.pixels);
    renderPassRange(backend, probeFrame(frame_), firstPass_, passes_, cyclePasses_);
    backend.readProbe(addedAccum);
    addToProbe(probe_, probeAccum, added, addedAccum);
    backend.resizeProbe(probe_.pixels);
    backend.writeProbe(probeAccum);
}

bool ErrorTracker::estimateIfDue(Backend& backend, PassScheduler& batches, double renderSeconds) {
    if (how_.noiseless && target_ > 0.0) {  // the error is 0 from the first pass
        lastRelError_ = 0.0;
        reached_ = true;
        return false;
    }
    if (how_.displayInterval > 0.0 && !batches.estimateScheduled() &&
        renderSeconds - lastReadSeconds_ >= how_.displayInterval)
        batches.estimateSoon();
    if (!batches.estimateDue()) return false;
    return read(backend, batches, renderSeconds);
}

bool ErrorTracker::read(Backend& backend, PassScheduler& batches, double renderSeconds) {
    if (probing_) growRenderedProbe(backend);
    const ErrorEstimate e = estimateRenderError(backend, probe_, accum_);
    ++readings_;
    lastRelError_ = e.relError;
    if (e.available) {
        estimate_ = e;
        if (target_ > 0.0 && e.relError <= target_) reached_ = true;
    }
    if (how_.displayInterval > 0.0) {
        batches.estimateDone();
        lastReadSeconds_ = renderSeconds;
        std::vector<AccumPixel>().swap(accum_);  // no second copy of the image held between display readings
    } else if (!reached_) {
        batches.estimateWhenPredicted(e.available ? e.relError : 0.0, target_);
    }
    return e.available;
}

void ErrorTracker::finish(Backend& backend) {
    if (probing_ && grownAt_ != passes_) growRenderedProbe(backend);
}

}  // namespace trazo
