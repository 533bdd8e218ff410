#include "model/progressive_accumulation.h"

#include <algorithm>
#include <chrono>

#include "core/rng.h"
#include "render/frame_setup.h"
#include "render/progressive_render.h"

namespace trazo {

ProgressiveAccumulation::~ProgressiveAccumulation() {
    if (worker_.joinable()) worker_.join();  // an exception in the batch has nowhere to go now
}

void ProgressiveAccumulation::restart(Backend& backend, const Scene& scene, const SceneArrays& arrays,
                                      uint32_t width, uint32_t height, uint32_t seed) {
    waitIdle(backend);
    backend.reset();
    arrays_ = &arrays;
    camera_ = makeFrameParams(scene, width, height, seed).camera;
    seed_ = seed;
    width_ = width;
    height_ = height;
    cyclePasses_ = fullCyclePasses(arrays, StrataBlocks::ones());
    segment_ = 0;
    startSegment(firstBlocks_);
    tracker_.restart(frame_, segmentCycle_, 0, batches_);
    passes_ = 0;
    samples_ = 0.0;
    rays_ = 0;
    renderSeconds_ = 0.0;
    ++generation_;
    convergence_.clear();
}

void ProgressiveAccumulation::setBlocks(const StrataBlocks& first, double growthPassSeconds) {
    firstBlocks_ = first;
    growthPassSeconds_ = growthPassSeconds;
}

void ProgressiveAccumulation::setTargetError(double target) { tracker_.setTarget(target); }

void ProgressiveAccumulation::startSegment(const StrataBlocks& blocks) {
    const uint32_t seed = segment_ == 0 ? seed_ : hashCombine(seed_, segment_);
    frame_ = FrameParams{camera_, seed, blocks};
    segmentCycle_ = fullCyclePasses(*arrays_, blocks);
    // In passes of the first segment's blocks: 1 there, so a session that never grows accumulates exactly what
    // `--render --blocks B` does.
    frame_.sampleWeight = float(fullCyclePasses(*arrays_, firstBlocks_)) / float(segmentCycle_);
}

void ProgressiveAccumulation::start(Backend& backend, uint32_t count) {
    waitIdle(backend);
    if (tracker_.targetReached()) return;
    count = std::min(count, kMaxProgressivePasses - passes_);
    // With growth on, batches end at the segment's cycle boundaries, where growBlocks may start a new one.
    if (growthPassSeconds_ > 0.0) count = std::min(count, segmentCycle_ - batches_.passes() % segmentCycle_);
    // An estimate due: the batch ends where the halves are balanced (the pixels do not depend on batching).
    count = batches_.upToEstimate(count);
    if (count == 0) return;
    batchPasses_ = count;
    std::promise<double> promise;
    batch_ = promise.get_future();
    worker_ = std::thread([backend = &backend, frame = frame_, first = batches_.passes(), count, cycle = segmentCycle_,
                           done = onBatchDone_, promise = std::move(promise)]() mutable {
        const auto t0 = std::chrono::steady_clock::now();
        try {
            renderPassRange(*backend, frame, first, count, cycle);
            promise.set_value(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        } catch (...) {
            promise.set_exception(std::current_exception());
        }
        if (done) done();  // after the result is ready, so the woken loop finds it
    });
}

bool ProgressiveAccumulation::busy(Backend& backend) {
    if (!batch_.valid()) return false;
    if (batch_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return true;
    worker_.join();
    const double seconds = batch_.get();  // rethrows the batch's exception
    passes_ += batchPasses_;
    tracker_.rendered(backend, batchPasses_, batches_);
    batches_.finished(batchPasses_, seconds);
    samples_ += double(batchPasses_) * frame_.sampleWeight;
    renderSeconds_ += seconds;
    secondsPerPixelPass_ = batches_.secondsPerPass() / (double(width_) * height_);
    rays_ = backend.raysTraced();
    ++generation_;
    if (tracker_.estimateIfDue(backend, batches_, renderSeconds_))
        convergence_.push_back({renderSeconds_, tracker_.estimate().relError, passes_});
    growBlocks();
    return false;
}

void ProgressiveAccumulation::waitIdle(Backend& backend) {
    if (batch_.valid()) batch_.wait();
    busy(backend);
}

void ProgressiveAccumulation::growBlocks() {
    if (growthPassSeconds_ <= 0.0 || batches_.passes() % segmentCycle_ != 0) return;
    if (2.0 * batches_.secondsPerPass() > growthPassSeconds_) return;
    const StrataBlocks limit = headlessBlocks(*arrays_), b = frame_.blocks;
    auto doubled = [](uint32_t t, uint32_t max) { return t >= max / 2 ? max : 2 * t; };
    const StrataBlocks grown{doubled(b.antialiasing, limit.antialiasing), doubled(b.areaLight, limit.areaLight),
                             doubled(b.indirect, limit.indirect), doubled(b.lightAtIndirect, limit.lightAtIndirect)};
    if (grown == b) return;
    ++segment_;
    startSegment(grown);
    batches_.startSegment(segmentCycle_, 2.0);  // until measured: batches sized for the larger passes
    secondsPerPixelPass_ *= 2.0;
}

}  // namespace trazo
