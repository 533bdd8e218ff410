// RenderSettings: the render settings kernels need (the SceneSettings block), as plain values (from SceneSettings).
#pragma once

#include <cstdint>

#include "core/integrator_kinds.h"
#include "core/vec3.h"

namespace trazo {

// SPEC §7's LightSampling: how the path integrator estimates light (all three converge to the same image).
enum class LightSampling : uint32_t { Mis, Nee, Bsdf };

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
    // SPEC §7 (Integrator path): scatterings a path may take beyond the first (MaxBounces), and the estimator.
    uint32_t maxBounces = 64;
    LightSampling lightSampling = LightSampling::Mis;
};

}  // namespace trazo
