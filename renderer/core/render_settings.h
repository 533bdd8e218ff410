// RenderSettings: the render settings kernels need (the SceneSettings block), as plain values (from SceneSettings).
#pragma once

#include <cstdint>

#include "core/integrator_kinds.h"
#include "core/vec3.h"

namespace trazo {

struct RenderSettings {
    Vec3 background;
    uint32_t reflectionQuality;
    uint32_t reflectionSteps;
    uint32_t indirectQuality;
    float colorBleeding;
    uint32_t antialiasing;  // 1, 4 or 16
    // SPEC §6's thin lens (the Camera block's, fixed at flatten: the viewer's orbit keeps the focus distance, as
    // a real camera's focus ring does): radius (0: a pinhole), distance in focus along the view, and q of its q
    // rings × 2q sectors of strata (≥ 1). Here rather than in the CameraFrame of every pass, whose size the
    // CUDA kernels' spills follow (+52 bytes in the indirect-light variants when it held these three).
    float aperture;
    float focalDistance;
    uint32_t lensQuality;
    IntegratorKind integrator = IntegratorKind::Thesis;
};

}  // namespace trazo
