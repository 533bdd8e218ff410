// ViewerSession: edit → flatten → upload → restart, then batches of passes on a worker thread through the same
// renderPassRange() as the headless render, so N passes here equal `trazo --render --spp N`.
#include "model/viewer_session.h"

#include <algorithm>

#include "render/frame_setup.h"

namespace trazo {

ViewerSession::ViewerSession(Scene scene, std::unique_ptr<Backend> backend, uint32_t seed, uint32_t width,
                             uint32_t height)
    : scene_(std::move(scene)), fileScene_(scene_), backend_(std::move(backend)), seed_(seed) {
    requestedWidth_ = width ? width : uint32_t(std::max(scene_.settings.renderWidth, 1));
    requestedHeight_ = height ? height : uint32_t(std::max(scene_.settings.renderHeight, 1));
    dirty_ = kDirtyScene | kDirtySize | kDirtyCamera;
    applyEdits();
}

ViewerSession::~ViewerSession() = default;

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
    upload_.sendWholeNext();
    dirty_ |= kDirtyScene | kDirtySize;
    applyEdits();
}

void ViewerSession::replaceScene(Scene scene, bool keepSize) {
    waitIdle();
    std::swap(scene_, scene);  // `scene` keeps the old one until the new one is uploaded
    const uint32_t oldWidth = requestedWidth_, oldHeight = requestedHeight_;
    if (!keepSize) {
        requestedWidth_ = uint32_t(std::max(scene_.settings.renderWidth, 1));
        requestedHeight_ = uint32_t(std::max(scene_.settings.renderHeight, 1));
    }
    upload_.sendWholeNext();  // nothing of the old scene is reused
    dirty_ |= kDirtyScene | kDirtySize | kDirtyCamera;
    try {
        applyEdits();
    } catch (...) {
        std::swap(scene_, scene);
        requestedWidth_ = oldWidth;
        requestedHeight_ = oldHeight;
        upload_.sendWholeNext();  // the backend may hold part of either scene: the next edit sends everything again
        dirty_ |= kDirtyScene;
        throw;
    }
    fileScene_ = scene_;
}

void ViewerSession::applyEdits() {
    waitIdle();
    if (dirty_ == kDirtyNone) return;
    upload_.clearReport();
    if ((dirty_ & kDirtyScene) || upload_.sendsWholeNext()) upload_.upload(scene_, *backend_);
    if (dirty_ & kDirtySize) {
        width_ = std::max((requestedWidth_ + previewDivisor_ - 1) / previewDivisor_, 1u);
        height_ = std::max((requestedHeight_ + previewDivisor_ - 1) / previewDivisor_, 1u);
        backend_->resize(width_, height_);  // reallocates, and clears
    }
    restartAccumulation();
    dirty_ = kDirtyNone;
}

void ViewerSession::restartAccumulation() {
    accumulation_.restart(*backend_, scene_, upload_.flat().arrays, width_, height_, seed_);
}

void ViewerSession::setBlocks(const StrataBlocks& first, double growthPassSeconds) {
    waitIdle();
    accumulation_.setBlocks(first, growthPassSeconds);
    restartAccumulation();
}

void ViewerSession::startPasses(uint32_t count) {
    applyEdits();
    accumulation_.start(*backend_, count);
}

std::optional<PickHit> ViewerSession::pick(float x, float y) {
    applyEdits();
    return pickObject(*backend_, scene_, upload_.flat().sources, requestedWidth_, requestedHeight_, x, y);
}

std::vector<int32_t> ViewerSession::objectIds(uint32_t width, uint32_t height) {
    applyEdits();
    return objectIdsOf(*backend_, scene_, width, height);
}

std::vector<Vec3> ViewerSession::image() {
    waitIdle();
    return readImage(*backend_);
}

}  // namespace trazo
