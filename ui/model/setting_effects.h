// What an edit of one SceneSettings or Camera row makes the viewer redo (host, no UI), and the image transform
// the viewer shows (SPEC §7's Image): the panels flag their rows with these, the display and the image export
// read displayTransformOf.
#pragma once

#include <string_view>

#include "core/view_transform.h"
#include "model/dirty_flags.h"
#include "scene/param_check.h"
#include "scene/scene.h"

namespace trazo {

// Exposure and ViewTransform change only how the estimate is shown (kDirtyDisplay: no restart); the other
// rows reach the kernels through flatten's RenderSettings (kDirtyScene: re-flatten, upload, restart). The
// render size is the widget's own (ParamWidget::commitOnExit, kDirtySize).
inline DirtyFlags sceneSettingEffect(const ParamInfo& row) {
    return row.name == "Exposure" || row.name == "ViewTransform" ? kDirtyDisplay : kDirtyScene;
}

// POV, POI and FOV make the next pass's camera frame (kDirtyCamera); the lens (Aperture, FocalDistance,
// LensQuality) is fixed at flatten in RenderSettings, so it re-flattens too.
inline DirtyFlags cameraSettingEffect(const ParamInfo& row) {
    const bool lens = row.name == "Aperture" || row.name == "FocalDistance" || row.name == "LensQuality";
    return lens ? (kDirtyCamera | kDirtyScene) : kDirtyCamera;
}

// The scene's Exposure and ViewTransform (Auto resolved by its Integrator): what the viewer's display and an
// 8-bit image saved from it apply to the estimate.
inline DisplayTransform displayTransformOf(const Scene& scene) {
    const SceneSettings& s = scene.settings;
    return displayTransform(s.exposure, s.viewTransform, s.integrator);
}

}  // namespace trazo
