// ViewerStats: the numbers of the viewer's closing line (host, no GL): when the first image and the first
// full-size image reached the screen, the frames drawn and batches started, and the frame rate while dragging.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace trazo {

class ViewerStats {
public:
    using Clock = std::chrono::steady_clock;

    explicit ViewerStats(Clock::time_point start) : start_(start) {}

    // A batch of passes started: it carries every edit made before it (moveInput).
    void batchStarted();
    // An object move changed the scene at `t` (the first of several before the next batch counts).
    void moveInput(Clock::time_point t);
    // A frame put a new image on screen at `shown`: the first after a move's batch ends that move's latency.
    // Returns it in seconds, or -1 when this image carries no move.
    double imageShown(Clock::time_point shown);
    // A frame reached the screen at `shown`; its work began at `began`. `image` and `fullImage`: whether an image
    // (a full-size one) is up by then; `dragging`: a drag goes on (frames of one drag are at most 0.5 s apart).
    void frameShown(Clock::time_point began, Clock::time_point shown, bool image, bool fullImage, bool dragging);

    uint64_t frames() const { return frames_; }
    // "first image after A s (full size after B s); C s open, N frames drawn; while dragging F fps (M frames,
    // W ms of work each); K batches", C counted to `now`; -1 for an image not shown yet. After object moves:
    // "; object moves shown after L ms on average (worst X ms, Q images)".
    std::string summary(Clock::time_point now) const;

private:
    Clock::time_point start_;
    uint64_t frames_ = 0, batches_ = 0;
    double firstImageSeconds_ = -1.0, fullImageSeconds_ = -1.0;
    uint64_t dragFrames_ = 0;  // frames drawn during drags, the time between them, and their own work
    double dragSeconds_ = 0.0, dragWorkSeconds_ = 0.0;
    Clock::time_point lastDragFrame_{};
    bool moveWaiting_ = false, moveInBatch_ = false;  // a move not yet in a batch; one in the running batch
    Clock::time_point moveAt_{}, batchMoveAt_{};
    uint64_t moveImages_ = 0;
    double moveSeconds_ = 0.0, worstMoveSeconds_ = 0.0;
};

}  // namespace trazo
