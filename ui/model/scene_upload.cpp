#include "model/scene_upload.h"

#include <chrono>

namespace trazo {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void SceneUpload::upload(const Scene& scene, Backend& backend) {
    UploadReport report;
    const auto t0 = std::chrono::steady_clock::now();
    FlattenResult next;
    try {
        next = flatten(scene, whole_ ? nullptr : &flat_);
    } catch (...) {
        whole_ = true;  // flat_ may have lost arrays to the failed flatten: never reuse it
        throw;
    }
    report.flattenSeconds = secondsSince(t0);
    report.meshesRebuilt = next.meshesBuilt;
    report.meshesReused = next.meshesReused;
    const auto t1 = std::chrono::steady_clock::now();
    report.changed = whole_ ? kAllArrays : changedArrays(flat_.arrays, next.arrays, next.reused);
    report.compareSeconds = secondsSince(t1);
    flat_ = std::move(next);
    const auto t2 = std::chrono::steady_clock::now();
    if (report.changed != kNoArrays) {
        whole_ = true;  // until the upload is whole
        backend.upload(flat_.arrays, report.changed);
        whole_ = false;
    }
    report.uploadSeconds = secondsSince(t2);
    report_ = report;
}

}  // namespace trazo
