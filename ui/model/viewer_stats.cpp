// ViewerStats: counting frames and drags, and the closing line's wording.
#include "model/viewer_stats.h"

#include <cstdio>

namespace trazo {
namespace {

double seconds(ViewerStats::Clock::duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

void ViewerStats::frameShown(Clock::time_point began, Clock::time_point shown, bool image, bool fullImage,
                             bool dragging) {
    ++frames_;
    if (image && firstImageSeconds_ < 0) firstImageSeconds_ = seconds(shown - start_);
    if (fullImage && fullImageSeconds_ < 0) fullImageSeconds_ = seconds(shown - start_);
    if (!dragging) return;
    if (lastDragFrame_ != Clock::time_point{} && seconds(shown - lastDragFrame_) < 0.5) {
        ++dragFrames_;
        dragSeconds_ += seconds(shown - lastDragFrame_);
        dragWorkSeconds_ += seconds(shown - began);
    }
    lastDragFrame_ = shown;
}

void ViewerStats::batchStarted() {
    ++batches_;
    if (!moveWaiting_) return;
    moveWaiting_ = false;
    moveInBatch_ = true;
    batchMoveAt_ = moveAt_;
}

void ViewerStats::moveInput(Clock::time_point t) {
    if (moveWaiting_) return;
    moveWaiting_ = true;
    moveAt_ = t;
}

double ViewerStats::imageShown(Clock::time_point shown) {
    if (!moveInBatch_) return -1.0;
    moveInBatch_ = false;
    const double latency = seconds(shown - batchMoveAt_);
    ++moveImages_;
    moveSeconds_ += latency;
    if (latency > worstMoveSeconds_) worstMoveSeconds_ = latency;
    return latency;
}

std::string ViewerStats::summary(Clock::time_point now) const {
    char text[512];
    std::snprintf(text, sizeof text,
                  "first image after %.3f s (full size after %.3f s); %.2f s open, %llu frames drawn; while dragging "
                  "%.1f fps (%llu frames, %.1f ms of work each); %llu batches",
                  firstImageSeconds_, fullImageSeconds_, seconds(now - start_), (unsigned long long)frames_,
                  dragSeconds_ > 0 ? double(dragFrames_) / dragSeconds_ : 0.0, (unsigned long long)dragFrames_,
                  dragFrames_ ? 1e3 * dragWorkSeconds_ / double(dragFrames_) : 0.0, (unsigned long long)batches_);
    std::string out = text;
    if (moveImages_) {
        std::snprintf(text, sizeof text, "; object moves shown after %.1f ms on average (worst %.1f ms, %llu images)",
                      1e3 * moveSeconds_ / double(moveImages_), 1e3 * worstMoveSeconds_,
                      (unsigned long long)moveImages_);
        out += text;
    }
    return out;
}

}  // namespace trazo
