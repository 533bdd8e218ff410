// ViewerSession: the model behind the viewer window, in three parts it composes: the edited scene and what the
// backend holds of it (SceneUpload), the converging image on a worker thread (ProgressiveAccumulation), and
// questions about what the camera sees (image_queries.h). Edits mark what changed; applyEdits() re-flattens and
// sends only the arrays that differ (or only resets, for the camera), and restarts the accumulation. No window
// and no GL: the tests drive it directly.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "backends/backend.h"
#include "model/dirty_flags.h"
#include "model/image_queries.h"
#include "model/progressive_accumulation.h"
#include "model/scene_upload.h"
#include "scene/object_id.h"
#include "scene/scene.h"

namespace trazo {

class ViewerSession {
public:
    // The window's batch budget: long enough that the per-batch display update is a small share, short enough
    // that an edit restarts the image quickly. The window redraws independently of it.
    static constexpr double kBatchSeconds = 1.0 / 30.0;

    // `scene` must have been read without errors. The render size starts as width × height (0: the scene's
    // RenderWidth × RenderHeight). Uploads, allocates and clears: ready for passes.
    ViewerSession(Scene scene, std::unique_ptr<Backend> backend, uint32_t seed, uint32_t width = 0, uint32_t height = 0);
    ~ViewerSession();  // waits for a running batch
    ViewerSession(const ViewerSession&) = delete;
    ViewerSession& operator=(const ViewerSession&) = delete;

    // The scene being edited (the UI thread's, even while a batch runs: batches see only the backend's copy).
    Scene& scene() { return scene_; }
    const Scene& scene() const { return scene_; }
    const Scene& fileScene() const { return fileScene_; }  // as read, for "reset camera" and comparisons
    // kDirtyDisplay is the display's alone: the session ignores it (the accumulation goes on).
    void markDirty(DirtyFlags flags) { dirty_ |= flags & ~kDirtyDisplay; }
    DirtyFlags dirty() const { return dirty_; }
    void setRenderSize(uint32_t width, uint32_t height);  // marks kDirtySize when it differs
    // Renders at 1/divisor of the render size in each direction (a preview while the user moves things);
    // 1 = full size. Marks kDirtySize when it changes.
    void setPreviewDivisor(uint32_t divisor);
    uint32_t previewDivisor() const { return previewDivisor_; }
    uint32_t renderWidth() const { return requestedWidth_; }  // the full size (what screenshots hold)
    uint32_t renderHeight() const { return requestedHeight_; }
    void replaceBackend(std::unique_ptr<Backend> backend);  // waits, uploads, allocates, clears
    // A new scene (opened at run time; read without errors): it becomes fileScene() too, pending edits of the
    // old one are dropped, and the render size becomes the scene's RenderWidth × RenderHeight unless
    // keepSize. Flattens and uploads it whole. If that throws, the old scene stays (and the exception
    // reaches the caller).
    void replaceScene(Scene scene, bool keepSize = false);
    // Redoes what the dirty flags say (waits for the batch first) and clears the accumulation.
    void applyEdits();
    const UploadReport& lastUpload() const { return upload_.report(); }  // of the last applyEdits
    const Diagnostics& flattenWarnings() const { return upload_.flat().warnings; }  // read but not drawn
    const SceneArrays& arrays() const { return upload_.flat().arrays; }            // as last uploaded

    // What the camera sees, through the backend's own ray query (image_queries.h), for the scene the next image
    // shows (pending edits are applied first). (x, y) in pixels of the full render size.
    std::optional<PickHit> pick(float x, float y);
    std::vector<int32_t> objectIds(uint32_t width, uint32_t height);
    std::optional<ObjectId> objectOf(int32_t answer) const { return objectOfAnswer(upload_.flat().sources, answer); }
    std::vector<uint8_t> selectionMask(const std::vector<int32_t>& ids, const ObjectId& selected) const {
        return selectionMaskOf(upload_.flat().sources, ids, selected);
    }

    // Batches of passes (ProgressiveAccumulation), one at a time. startPasses applies pending edits first.
    void startPasses(uint32_t count);
    void renderPasses(uint32_t count) {  // synchronous (tests, automation)
        startPasses(count);
        waitIdle();
    }
    bool busy() { return accumulation_.busy(*backend_); }  // collects a finished batch (rethrows its exception)
    void waitIdle() { accumulation_.waitIdle(*backend_); }
    uint32_t passesForBudget(double seconds) const { return accumulation_.passesFor(seconds); }
    // The blocks every restart begins with (default: one stratum per pass), and growth while a pass at twice
    // the blocks takes at most `growthPassSeconds` (0, the default: never; the image then equals
    // `trazo --render --blocks B --spp N`). Restarts the accumulation.
    void setBlocks(const StrataBlocks& first, double growthPassSeconds);
    void setTargetError(double target) { accumulation_.setTargetError(target); }
    // Called on the worker thread when a batch ends (the window wakes its event loop with it).
    void setOnBatchDone(std::function<void()> callback) { accumulation_.setOnBatchDone(std::move(callback)); }
    const ProgressiveAccumulation& accumulation() const { return accumulation_; }

    // The converging image's state (passes, samples, blocks, rays, error estimate, …: ProgressiveAccumulation
    // says what each means) is accumulation()'s. The backend is meaningful while !busy().
    Backend& backend() { return *backend_; }
    uint32_t width() const { return width_; }  // the accumulation's size (smaller during a preview)
    uint32_t height() const { return height_; }
    std::vector<Vec3> image();  // sum / count per pixel, row 0 = top (waits for the batch)

private:
    void restartAccumulation();

    Scene scene_, fileScene_;
    std::unique_ptr<Backend> backend_;
    uint32_t seed_;
    uint32_t width_ = 0, height_ = 0, requestedWidth_ = 0, requestedHeight_ = 0, previewDivisor_ = 1;
    DirtyFlags dirty_ = kDirtyNone;
    SceneUpload upload_;
    ProgressiveAccumulation accumulation_;  // last: its worker is joined before the backend goes
};

}  // namespace trazo
