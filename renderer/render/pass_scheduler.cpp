#include "render/pass_scheduler.h"

#include <algorithm>

#include "render/error_tracker.h"

namespace trazo {

void PassScheduler::restart(uint32_t cyclePasses, bool probed) {
    step_ = probed ? 1u : splitsHalves(cyclePasses) ? 2u * cyclePasses : 0u;
    passes_ = 0;
    secondsPerPass_ = 0.0;
    nextEstimate_ = kNever;
}

void PassScheduler::startSegment(uint32_t cyclePasses, double costScale) {
    const bool due = estimateScheduled();
    const double pace = secondsPerPass_ * costScale;
    restart(cyclePasses, step_ == 1);
    secondsPerPass_ = pace;
    if (due) estimateSoon();
}

uint32_t PassScheduler::passesFor(double seconds) const {
    if (secondsPerPass_ <= 0.0) return 1;
    return uint32_t(std::clamp(seconds / secondsPerPass_, 1.0, double(kMaxBatchPasses)));
}

uint32_t PassScheduler::upToEstimate(uint32_t count) const {
    if (nextEstimate_ > passes_) return uint32_t(std::min<uint64_t>(count, nextEstimate_ - passes_));
    return count;
}

void PassScheduler::finished(uint32_t passes, double seconds) {
    passes_ += passes;
    secondsPerPass_ = seconds / std::max(passes, 1u);
}

uint64_t PassScheduler::unbiasedFrom(uint64_t passes) const {
    if (step_ == 0) return kNever;
    return (passes + step_ - 1) / step_ * step_;
}

void PassScheduler::estimateSoon() { nextEstimate_ = unbiasedFrom(std::max(passes_, 1u)); }

void PassScheduler::estimateWhenPredicted(double relError, double target) {
    double predicted = 2.0 * passes_;
    if (relError > 0.0 && target > 0.0) {
        const double ratio = relError / target;
        predicted = std::min(predicted, 1.05 * passes_ * ratio * ratio);
    }
    nextEstimate_ = unbiasedFrom(std::max<uint64_t>(uint64_t(predicted), uint64_t(passes_) + 1));
}

}  // namespace trazo
