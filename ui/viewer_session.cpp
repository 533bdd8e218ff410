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
    renderSeconds_ += seconds;
    secondsPerPass_ = seconds / std::max(batchPasses_, 1u);
    secondsPerPixelPass_ = secondsPerPass_ / (double(width_) * height_);
    rays_ = backend_->raysTraced();
    ++generation_;
    return false;
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
    frame_ = makeFrameParams(scene_, width_, height_, seed_);
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
    passes_ = 0;
    rays_ = 0;
    renderSeconds_ = 0.0;
    ++generation_;
}

void ViewerSession::startPasses(uint32_t count) {
    applyEdits();
    count = std::min(count, kMaxProgressivePasses - passes_);
    if (count == 0) return;
    batchPasses_ = count;
    std::promise<double> promise;
    batch_ = promise.get_future();
    // The worker sees only the backend and copies of what the passes need; the UI thread keeps the scene.
    worker_ = std::thread([backend = backend_.get(), frame = frame_, first = passes_, count, cycle = cyclePasses_,
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
