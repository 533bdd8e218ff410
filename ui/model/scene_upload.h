// SceneUpload: what the viewer's backend holds of the edited scene. upload() re-flattens (an unchanged mesh
// keeps its BVH: flatten's `previous`) and sends the backend only the arrays that differ from the last upload,
// or everything after sendWholeNext() or a failure. Host code, no window.
#pragma once

#include "backends/backend.h"
#include "flatten/array_mask.h"
#include "flatten/flatten.h"
#include "scene/scene.h"

namespace trazo {

// What the last upload re-flattened and re-sent.
struct UploadReport {
    ArrayMask changed = kNoArrays;  // arrays sent to the backend (none: a camera or size edit)
    uint32_t meshesRebuilt = 0;     // meshes whose BVH was built again
    uint32_t meshesReused = 0;
    double flattenSeconds = 0.0;    // flatten(), with reuse
    double compareSeconds = 0.0;    // finding the changed arrays
    double uploadSeconds = 0.0;     // Backend::upload of the changed arrays
};

class SceneUpload {
public:
    // Flattens `scene` and sends `backend` what changed. If flattening or sending throws, the next upload sends
    // everything (the backend may hold part of either scene) and the exception reaches the caller.
    void upload(const Scene& scene, Backend& backend);
    void sendWholeNext() { whole_ = true; }  // a new backend, or a new scene: nothing to reuse
    bool sendsWholeNext() const { return whole_; }
    void clearReport() { report_ = UploadReport{}; }  // an edit that re-sends nothing (camera, size)

    const FlattenResult& flat() const { return flat_; }  // as last uploaded
    const UploadReport& report() const { return report_; }

private:
    FlattenResult flat_;
    bool whole_ = true;  // the backend holds nothing of flat_ yet
    UploadReport report_;
};

}  // namespace trazo
