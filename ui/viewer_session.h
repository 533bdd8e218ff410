// ViewerSession: the model behind the viewer window: the edited scene, its backend and the progressive
// accumulation. Edits mark what changed; applyEdits() re-flattens (reusing unchanged meshes' BVHs) and sends
// the backend only the arrays that differ (or only resets, for the camera), and restarts the accumulation. Passes run in batches on a worker thread, so the window stays
// responsive while the backend works. No window and no GL: the tests drive it directly.
//
// Blocks of strata (integrator/strata.h) start at one stratum per pass, so the first image after an edit is as
// fast as a pass can be. With growth on, whenever a cycle of the current blocks is complete and a pass at
// twice the blocks would still fit the pass budget, the accumulation goes on in a new segment: blocks
// doubled (up to the headless render's), a seed of its own, and samples weighted by the first segment's
// passes each stands for (FrameParams::sampleWeight). Every segment is whole cycles, an exact stratified
// estimate.
#pragma once

#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "backends/backend.h"
#include "device/flatten.h"
#include "dirty_flags.h"
#include "render/error_estimate.h"
#include "render/pass_scheduler.h"
#include "scene/object_id.h"
#include "scene/scene.h"

namespace trazo {

// What a click on the image found: the object (or area light) nearest along the camera ray, at distance t,
// at `point` (world space).
struct PickHit {
    ObjectId object;
    float t;
    Vec3 point;
};

// What the last applyEdits (or replaceScene) re-flattened and re-sent.
struct UploadReport {
    ArrayMask changed = kNoArrays;  // arrays sent to the backend (none: a camera or size edit)
    uint32_t meshesRebuilt = 0;     // meshes whose BVH was built again
    uint32_t meshesReused = 0;
    double flattenSeconds = 0.0;    // flatten(), with reuse
    double compareSeconds = 0.0;    // finding the changed arrays
    double uploadSeconds = 0.0;     // Backend::upload of the changed arrays
};

// One point of the convergence plot: the estimated relative error (error_estimate.h) after `seconds` of
// rendering since the last reset.
struct ConvergencePoint {
    double seconds;
    double relError;
    uint32_t passes;
};

class ViewerSession {
public:
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
    void markDirty(DirtyFlags flags) { dirty_ |= flags; }
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
    const UploadReport& lastUpload() const { return lastUpload_; }

    // Picking through the backend's own ray query (RayQueryKind::Object, the image's traversal). (x, y) in
    // pixels of the full render size, (0, 0) the image's top-left corner (pixel centres at +0.5). Applies
    // pending edits first (waiting for a running batch), so it answers for the scene the next image shows.
    // Nothing there (background): nullopt.
    std::optional<PickHit> pick(float x, float y);
    // For every pixel centre of a width × height image of the same camera (row 0 = top): what the camera ray
    // hits first, as RayAnswer::object (an index into arrays().objects, areaLightAnswer(i), or kMissAnswer).
    // Applies pending edits first, like pick.
    std::vector<int32_t> objectIds(uint32_t width, uint32_t height);
    // The host object of each entry of arrays().objects (parallel to it).
    const std::vector<ObjectId>& objectSources() const { return flat_.sources; }
    // The host object or area light of a RayAnswer::object; nullopt for a miss.
    std::optional<ObjectId> objectOf(int32_t answer) const;
    // 1 where objectIds' entry is `selected`, else 0 (the selection's outline is this mask's edge).
    std::vector<uint8_t> selectionMask(const std::vector<int32_t>& ids, const ObjectId& selected) const;

    // Convergence. At the end of a batch whose passes complete an even number of cycles of the current segment
    // (where the two halves are equally stratified, progressive_render.h), at most every kEstimateInterval
    // seconds of rendering, the error is estimated from the accumulation's halves (estimateError) and added to
    // the series; batches are cut at those points when an estimate is due. While blocks grow, segments are
    // single cycles and nothing is estimated; after growth the earlier segments make the estimate approximate.
    static constexpr double kEstimateInterval = 0.25;
    const std::vector<ConvergencePoint>& convergence() const { return convergence_; }  // since the last reset
    const ErrorEstimate& errorEstimate() const { return estimate_; }  // the latest (available false: none yet)
    // Stops batches once an estimate reaches relError <= target (0: never stop, the default). Kept across
    // resets; targetReached() starts false again after each.
    void setTargetError(double target);
    double targetError() const { return targetError_; }
    bool targetReached() const { return targetReached_; }

    // Batches of passes, one at a time. startPasses applies pending edits first, and starts nothing once the
    // target error is reached. A batch may end before `count`: at the segment's cycle end while blocks grow,
    // and at an even cycle end when an error estimate is due (the pixels do not depend on batching).
    void startPasses(uint32_t count);
    void renderPasses(uint32_t count) {  // synchronous (tests, automation)
        startPasses(count);
        waitIdle();
    }
    // True while a batch runs; collects a finished one (and rethrows its exception, e.g. a CUDA error).
    bool busy();
    void waitIdle();
    // Redoes what the dirty flags say (waits for the batch first) and clears the accumulation.
    void applyEdits();
    // Passes for the next batch so that it takes about `seconds` (1 right after a reset: first image fast).
    uint32_t passesForBudget(double seconds) const;
    // The window's batch budget: long enough that the per-batch display update is a small share, short enough
    // that an edit restarts the image quickly. The window redraws independently of it.
    static constexpr double kBatchSeconds = 1.0 / 30.0;
    // Measured cost of one pass per pixel (0 before the first batch): predicts a pass at another size.
    double secondsPerPixelPass() const { return secondsPerPixelPass_; }
    // The blocks every restart begins with (default: one stratum per pass), and growth while a pass at twice
    // the blocks takes at most `growthPassSeconds` (0, the default: never; the image then equals
    // `trazo --render --blocks B --spp N`). Restarts the accumulation.
    void setBlocks(const StrataBlocks& first, double growthPassSeconds);
    const StrataBlocks& blocks() const { return frame_.blocks; }
    // Called on the worker thread when a batch ends (the window wakes its event loop with it).
    void setOnBatchDone(std::function<void()> callback) { onBatchDone_ = std::move(callback); }

    // The accumulation; meaningful while !busy().
    Backend& backend() { return *backend_; }
    uint32_t width() const { return width_; }  // the accumulation's size (smaller during a preview)
    uint32_t height() const { return height_; }
    uint32_t passes() const { return passes_; }  // since the last reset
    // Passes weighted by their samples' weights: the passes of the first segment's blocks (one stratum per grid,
    // unless setBlocks says otherwise) they are worth.
    double samples() const { return samples_; }
    double blocksWeight() const { return frame_.sampleWeight; }  // samples a pass of the current segment adds
    uint32_t cyclePasses() const { return cyclePasses_; }
    uint64_t rays() const { return rays_; }
    double renderSeconds() const { return renderSeconds_; }  // batch time since the last reset
    uint64_t generation() const { return generation_; }      // changes whenever the accumulation does
    uint32_t seed() const { return seed_; }
    // What of the scene is read but not drawn (flatten's warnings), as last uploaded.
    const Diagnostics& flattenWarnings() const { return flat_.warnings; }
    const SceneArrays& arrays() const { return flat_.arrays; }  // as last uploaded
    std::vector<Vec3> image();  // sum / count per pixel, row 0 = top (waits for the batch)

private:
    void uploadScene();
    void clearAccumulation();
    void estimateAfterBatch();                      // at the end of a batch: a convergence point when due
    // Camera rays of a width × height image through image positions (x, y), answered by the backend.
    std::vector<RayQuery> cameraRays(uint32_t width, uint32_t height, const std::vector<float>& xy) const;
    void startSegment(const StrataBlocks& blocks);  // frame_ for a new segment from the current pass on
    void growBlocks();                              // at the end of a batch: a larger segment when it pays

    Scene scene_, fileScene_;
    std::unique_ptr<Backend> backend_;
    uint32_t seed_;
    uint32_t width_ = 0, height_ = 0, requestedWidth_ = 0, requestedHeight_ = 0, previewDivisor_ = 1;
    FlattenResult flat_;
    bool uploadAll_ = true;  // the backend holds nothing of flat_ yet (new session, backend or scene)
    UploadReport lastUpload_;
    FrameParams frame_{};
    uint32_t cyclePasses_ = 1;      // of one stratum per pass
    uint32_t segment_ = 0;          // segments since the last reset
    uint32_t segmentCycle_ = 1;     // fullCyclePasses of its blocks
    PassScheduler batches_;         // counts the current segment's passes
    StrataBlocks firstBlocks_{};    // setBlocks
    double growthPassSeconds_ = 0;
    DirtyFlags dirty_ = kDirtyNone;

    std::thread worker_;
    std::future<double> batch_;  // seconds the batch took
    uint32_t batchPasses_ = 0;
    std::function<void()> onBatchDone_;

    uint32_t passes_ = 0;
    double samples_ = 0.0;
    uint64_t rays_ = 0;
    double renderSeconds_ = 0.0;
    double secondsPerPixelPass_ = 0.0;
    uint64_t generation_ = 0;

    std::vector<ConvergencePoint> convergence_;
    ErrorEstimate estimate_;
    double lastEstimateSeconds_ = 0.0;   // renderSeconds_ at the last try
    double targetError_ = 0.0;
    bool targetReached_ = false;
};

}  // namespace trazo
