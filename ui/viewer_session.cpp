// ViewerSession: edit → flatten → upload → reset, and batches of passes on a worker thread through the same
// renderPassRange() as the headless render, so N passes here equal `trazo --render --spp N`.
#include "viewer_session.h"

#include <algorithm>
#include <chrono>

#include "render/frame_setup.h"
#include "render/progressive_render.h"

namespace trazo {

ViewerSession::ViewerSession(Scene scene, std::unique_ptr<Backend> backend, uint32_t seed, uint32_t width,
                             uint32_t height)
    : scene_(std::move(scene)), fileScene_(scene_), backend_(std::move(backend)), seed_(seed) {
    requestedWidth_ = width ? width : uint32_t(std::max(scene_.settings.renderWidth, 1));
    requestedHeight_ = height ? height : uint32_t(std::max(scene_.settings.renderHeight, 1));
    dirty_ = kDirtyScene | kDirtySize | kDirtyCamera;
    applyEdits();
}

ViewerSession::~ViewerSession() {
    if (worker_.joinable()) worker_.join();  // an exception in the batch has nowhere to go now
}

void ViewerSession::setRenderSize(uint32_t width, uint32_t height) {
    width = std::max(width, 1u);
    height = std::max(height, 1u);
    if (width == requestedWidth_ && height == requestedHeight_) return;
    requestedWidth_ = width;
    requestedHeight_ = height;
    dirty_ |= kDirtySize;
}

void ViewerSession::setPreviewDivisor(uint32_t divisor) {
    divisor = std::max(divisor, 1u);
    if (divisor == previewDivisor_) return;
    previewDivisor_ = divisor;
    dirty_ |= kDirtySize;
}

void ViewerSession::replaceBackend(std::unique_ptr<Backend> backend) {
    waitIdle();
    backend_ = std::move(backend);
    dirty_ |= kDirtyScene | kDirtySize;
    applyEdits();
}

bool ViewerSession::busy() {
    if (!batch_.valid()) return false;
    if (batch_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return true;
    worker_.join();
    const double seconds = batch_.get();  // rethrows the batch's exception
    passes_ += batchPasses_;
    segmentPasses_ += batchPasses_;
    samples_ += double(batchPasses_) * frame_.sampleWeight;
    renderSeconds_ += seconds;
    secondsPerPass_ = seconds / std::max(batchPasses_, 1u);
    secondsPerPixelPass_ = secondsPerPass_ / (double(width_) * height_);
    rays_ = backend_->raysTraced();
    ++generation_;
    growBlocks();
    return false;
}

void ViewerSession::setBlocks(const StrataBlocks& first, double growthPassSeconds) {
    waitIdle();
    firstBlocks_ = first;
    growthPassSeconds_ = growthPassSeconds;
    clearAccumulation();
}

void ViewerSession::startSegment(const StrataBlocks& blocks) {
    const uint32_t seed = segment_ == 0 ? seed_ : hashCombine(seed_, segment_);
    frame_ = makeFrameParams(scene_, width_, height_, seed, blocks);
    segmentCycle_ = fullCyclePasses(flat_.arrays, blocks);
    // In passes of the first segment's blocks: 1 there, so a session that never grows accumulates exactly what
    // `--render --blocks B` does.
    frame_.sampleWeight = float(fullCyclePasses(flat_.arrays, firstBlocks_)) / float(segmentCycle_);
    segmentPasses_ = 0;
}

void ViewerSession::growBlocks() {
    if (growthPassSeconds_ <= 0.0 || segmentPasses_ % segmentCycle_ != 0) return;
    if (2.0 * secondsPerPass_ > growthPassSeconds_) return;
    const StrataBlocks limit = headlessBlocks(flat_.arrays), b = frame_.blocks;
    auto doubled = [](uint32_t t, uint32_t max) { return t >= max / 2 ? max : 2 * t; };
    const StrataBlocks grown{doubled(b.antialiasing, limit.antialiasing), doubled(b.areaLight, limit.areaLight),
                             doubled(b.indirect, limit.indirect), doubled(b.lightAtIndirect, limit.lightAtIndirect)};
    if (grown == b) return;
    ++segment_;
    startSegment(grown);
    secondsPerPixelPass_ *= 2.0;  // until measured: batches sized for the larger passes
}

void ViewerSession::waitIdle() {
    if (batch_.valid()) batch_.wait();
    busy();
}

void ViewerSession::applyEdits() {
    waitIdle();
    if (dirty_ == kDirtyNone) return;
    if (dirty_ & kDirtyScene) uploadScene();
    if (dirty_ & kDirtySize) {
        width_ = std::max((requestedWidth_ + previewDivisor_ - 1) / previewDivisor_, 1u);
        height_ = std::max((requestedHeight_ + previewDivisor_ - 1) / previewDivisor_, 1u);
        backend_->resize(width_, height_);  // reallocates, and clears
    }
    clearAccumulation();
    dirty_ = kDirtyNone;
}

void ViewerSession::uploadScene() {
    flat_ = flatten(scene_);
    cyclePasses_ = fullCyclePasses(flat_.arrays, StrataBlocks::ones());
    backend_->upload(flat_.arrays);  // the CUDA backend re-sends only the arrays that changed
}

void ViewerSession::clearAccumulation() {
    backend_->reset();
    segment_ = 0;
    startSegment(firstBlocks_);
    passes_ = 0;
    samples_ = 0.0;
    rays_ = 0;
    renderSeconds_ = 0.0;
    ++generation_;
}

void ViewerSession::startPasses(uint32_t count) {
    applyEdits();
    count = std::min(count, kMaxProgressivePasses - passes_);
    // With growth on, batches end at the segment's cycle boundaries, where growBlocks may start a new one.
    if (growthPassSeconds_ > 0.0) count = std::min(count, segmentCycle_ - segmentPasses_ % segmentCycle_);
    if (count == 0) return;
    batchPasses_ = count;
    std::promise<double> promise;
    batch_ = promise.get_future();
    // The worker sees only the backend and copies of what the passes need; the UI thread keeps the scene.
    worker_ = std::thread([backend = backend_.get(), frame = frame_, first = segmentPasses_, count, cycle = segmentCycle_,
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

uint32_t ViewerSession::passesForBudget(double seconds) const {
    if (passes_ == 0 || secondsPerPixelPass_ <= 0.0) return 1;
    const double perPass = secondsPerPixelPass_ * width_ * height_;
    return uint32_t(std::clamp(seconds / perPass, 1.0, 65536.0));
}

std::vector<Vec3> ViewerSession::image() {
    waitIdle();
    return readImage(*backend_);
}

}  // namespace trazo
