// ViewerSession: edit → flatten → upload → reset, and batches of passes on a worker thread through the same
// renderPassRange() as the headless render, so N passes here equal `trazo --render --spp N`.
#include "viewer_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>

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

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void ViewerSession::replaceBackend(std::unique_ptr<Backend> backend) {
    waitIdle();
    backend_ = std::move(backend);
    uploadAll_ = true;
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
    uploadAll_ = true;  // nothing of the old scene is reused
    dirty_ |= kDirtyScene | kDirtySize | kDirtyCamera;
    try {
        applyEdits();
    } catch (...) {
        std::swap(scene_, scene);
        requestedWidth_ = oldWidth;
        requestedHeight_ = oldHeight;
        uploadAll_ = true;  // the backend may hold part of either scene: the next edit sends everything again
        dirty_ |= kDirtyScene;
        throw;
    }
    fileScene_ = scene_;
}

bool ViewerSession::busy() {
    if (!batch_.valid()) return false;
    if (batch_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return true;
    worker_.join();
    const double seconds = batch_.get();  // rethrows the batch's exception
    passes_ += batchPasses_;
    batches_.finished(batchPasses_, seconds);
    samples_ += double(batchPasses_) * frame_.sampleWeight;
    renderSeconds_ += seconds;
    secondsPerPixelPass_ = batches_.secondsPerPass() / (double(width_) * height_);
    rays_ = backend_->raysTraced();
    ++generation_;
    estimateAfterBatch();
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
}

void ViewerSession::growBlocks() {
    if (growthPassSeconds_ <= 0.0 || batches_.passes() % segmentCycle_ != 0) return;
    if (2.0 * batches_.secondsPerPass() > growthPassSeconds_) return;
    const StrataBlocks limit = headlessBlocks(flat_.arrays), b = frame_.blocks;
    auto doubled = [](uint32_t t, uint32_t max) { return t >= max / 2 ? max : 2 * t; };
    const StrataBlocks grown{doubled(b.antialiasing, limit.antialiasing), doubled(b.areaLight, limit.areaLight),
                             doubled(b.indirect, limit.indirect), doubled(b.lightAtIndirect, limit.lightAtIndirect)};
    if (grown == b) return;
    ++segment_;
    startSegment(grown);
    batches_.startSegment(segmentCycle_, 2.0);  // until measured: batches sized for the larger passes
    secondsPerPixelPass_ *= 2.0;
}

void ViewerSession::waitIdle() {
    if (batch_.valid()) batch_.wait();
    busy();
}

void ViewerSession::applyEdits() {
    waitIdle();
    if (dirty_ == kDirtyNone) return;
    lastUpload_ = UploadReport{};
    if ((dirty_ & kDirtyScene) || uploadAll_) uploadScene();
    if (dirty_ & kDirtySize) {
        width_ = std::max((requestedWidth_ + previewDivisor_ - 1) / previewDivisor_, 1u);
        height_ = std::max((requestedHeight_ + previewDivisor_ - 1) / previewDivisor_, 1u);
        backend_->resize(width_, height_);  // reallocates, and clears
    }
    clearAccumulation();
    dirty_ = kDirtyNone;
}

// Meshes whose data and placement are unchanged keep their arrays (flatten's `previous`), and only the
// arrays that differ from the last upload are sent again.
void ViewerSession::uploadScene() {
    UploadReport report;
    const auto t0 = std::chrono::steady_clock::now();
    FlattenResult next;
    try {
        next = flatten(scene_, uploadAll_ ? nullptr : &flat_);
    } catch (...) {
        uploadAll_ = true;  // flat_ may have lost arrays to the failed flatten: never reuse it
        throw;
    }
    report.flattenSeconds = secondsSince(t0);
    report.meshesRebuilt = next.meshesBuilt;
    report.meshesReused = next.meshesReused;
    const auto t1 = std::chrono::steady_clock::now();
    report.changed = uploadAll_ ? kAllArrays : changedArrays(flat_.arrays, next.arrays, next.reused);
    report.compareSeconds = secondsSince(t1);
    flat_ = std::move(next);
    cyclePasses_ = fullCyclePasses(flat_.arrays, StrataBlocks::ones());
    const auto t2 = std::chrono::steady_clock::now();
    if (report.changed != kNoArrays) {
        uploadAll_ = true;  // until the upload is whole
        backend_->upload(flat_.arrays, report.changed);
        uploadAll_ = false;
    }
    report.uploadSeconds = secondsSince(t2);
    lastUpload_ = report;
}

void ViewerSession::clearAccumulation() {
    backend_->reset();
    segment_ = 0;
    startSegment(firstBlocks_);
    batches_.restart(segmentCycle_);
    batches_.estimateSoon();  // the first reading as soon as one is unbiased
    passes_ = 0;
    samples_ = 0.0;
    rays_ = 0;
    renderSeconds_ = 0.0;
    ++generation_;
    convergence_.clear();
    estimate_ = ErrorEstimate{};
    lastEstimateSeconds_ = 0.0;
    targetReached_ = false;
}

void ViewerSession::estimateAfterBatch() {
    if (!batches_.estimateScheduled() && renderSeconds_ - lastEstimateSeconds_ >= kEstimateInterval)
        batches_.estimateSoon();
    if (!batches_.estimateDue()) return;
    batches_.estimateDone();
    lastEstimateSeconds_ = renderSeconds_;
    std::vector<AccumPixel> accum;
    backend_->readAccumulation(accum);
    const ErrorEstimate e = estimateError(accum);
    if (!e.available) return;
    estimate_ = e;
    convergence_.push_back({renderSeconds_, e.relError, passes_});
    if (targetError_ > 0.0 && e.relError <= targetError_) targetReached_ = true;
}

void ViewerSession::setTargetError(double target) {
    targetError_ = std::max(target, 0.0);
    targetReached_ = targetError_ > 0.0 && estimate_.available && estimate_.relError <= targetError_;
}

void ViewerSession::startPasses(uint32_t count) {
    applyEdits();
    if (targetReached_) return;
    count = std::min(count, kMaxProgressivePasses - passes_);
    // With growth on, batches end at the segment's cycle boundaries, where growBlocks may start a new one.
    if (growthPassSeconds_ > 0.0) count = std::min(count, segmentCycle_ - batches_.passes() % segmentCycle_);
    // An estimate due: the batch ends where the halves are balanced (the pixels do not depend on batching).
    count = batches_.upToEstimate(count);
    if (count == 0) return;
    batchPasses_ = count;
    std::promise<double> promise;
    batch_ = promise.get_future();
    // The worker sees only the backend and copies of what the passes need; the UI thread keeps the scene.
    worker_ = std::thread([backend = backend_.get(), frame = frame_, first = batches_.passes(), count, cycle = segmentCycle_,
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

uint32_t ViewerSession::passesForBudget(double seconds) const { return batches_.passesFor(seconds); }

std::vector<RayQuery> ViewerSession::cameraRays(uint32_t width, uint32_t height, const std::vector<float>& xy) const {
    // The kernels' camera (makeFrameParams, generateCameraRay) for this size.
    const CameraFrame camera = makeFrameParams(scene_, width, height, seed_).camera;
    std::vector<RayQuery> queries(xy.size() / 2);
    for (size_t i = 0; i < queries.size(); ++i)
        queries[i] = RayQuery{generateCameraRay(camera, xy[2 * i], xy[2 * i + 1]), INFINITY};
    return queries;
}

std::optional<PickHit> ViewerSession::pick(float x, float y) {
    applyEdits();
    const std::vector<RayQuery> queries = cameraRays(requestedWidth_, requestedHeight_, {x, y});
    std::vector<RayAnswer> answers;
    backend_->traceRays(queries, RayQueryKind::Object, answers);
    const std::optional<ObjectId> object = objectOf(answers[0].object);
    if (!object) return std::nullopt;
    return PickHit{*object, answers[0].t, pointAt(queries[0].ray, answers[0].t)};
}

std::vector<int32_t> ViewerSession::objectIds(uint32_t width, uint32_t height) {
    applyEdits();
    std::vector<float> xy;
    xy.reserve(size_t(width) * height * 2);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            xy.push_back(float(x) + 0.5f);
            xy.push_back(float(y) + 0.5f);
        }
    }
    std::vector<RayAnswer> answers;
    backend_->traceRays(cameraRays(width, height, xy), RayQueryKind::Object, answers);
    std::vector<int32_t> ids(answers.size());
    for (size_t i = 0; i < answers.size(); ++i) ids[i] = answers[i].object;
    return ids;
}

std::optional<ObjectId> ViewerSession::objectOf(int32_t answer) const {
    if (isAreaLightAnswer(answer)) return ObjectId{ObjectId::Kind::AreaLight, areaLightOfAnswer(answer)};
    if (answer < 0 || size_t(answer) >= flat_.sources.size()) return std::nullopt;
    return flat_.sources[size_t(answer)];
}

std::vector<uint8_t> ViewerSession::selectionMask(const std::vector<int32_t>& ids, const ObjectId& selected) const {
    // The one answer that stands for `selected` (an object that draws nothing has none: an empty mask).
    int32_t want = kMissAnswer;
    if (selected.kind == ObjectId::Kind::AreaLight) want = areaLightAnswer(selected.index);
    for (size_t i = 0; i < flat_.sources.size() && !selected.isLight(); ++i)
        if (flat_.sources[i] == selected) want = int32_t(i);
    std::vector<uint8_t> mask(ids.size(), 0);
    if (want == kMissAnswer) return mask;
    for (size_t i = 0; i < ids.size(); ++i) mask[i] = ids[i] == want ? 1 : 0;
    return mask;
}

std::vector<Vec3> ViewerSession::image() {
    waitIdle();
    return readImage(*backend_);
}

}  // namespace trazo
