// RenderSettings: the render settings kernels need (the SceneSettings block), as plain values (from SceneSettings).
#pragma once

#include <cstdint>

#include "core/vec3.h"

namespace trazo {

struct RenderSettings {
    Vec3 background;
    uint32_t reflectionQuality;
    uint32_t reflectionSteps;
    uint32_t indirectQuality;
    float colorBleeding;
    uint32_t antialiasing;  // 1, 4 or 16
};

}  // namespace trazo
