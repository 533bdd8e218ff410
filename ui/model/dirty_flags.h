// DirtyFlags: what an edit changed, so the viewer redoes only that (panels and input return them).
#pragma once

#include <cstdint>

namespace trazo {

using DirtyFlags = uint32_t;
constexpr DirtyFlags kDirtyNone = 0;
constexpr DirtyFlags kDirtyCamera = 1u << 0;  // POV, POI, FOV: new FrameParams and a reset, no upload
constexpr DirtyFlags kDirtyScene = 1u << 1;   // settings, materials, lights, objects: flatten, upload, reset
constexpr DirtyFlags kDirtySize = 1u << 2;    // render size: reallocate the accumulation (and the display)
// Exposure, ViewTransform (SPEC §7): only how the display shows the same estimate; the accumulation goes on
// (ViewerSession ignores it, the frame loop redraws).
constexpr DirtyFlags kDirtyDisplay = 1u << 3;

}  // namespace trazo
