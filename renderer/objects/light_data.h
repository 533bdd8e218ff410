// The lights as kernels read them (SceneView::pointLights and areaLights): a point, and an area light's
// rectangle with its Subdivision grid.
#pragma once

#include <cstdint>

#include "core/vec3.h"
#include "objects/rectangle.h"

namespace trazo {

struct PointLightData {
    Vec3 position;
    Vec3 color;
};

struct AreaLightData {
    RectangleShape rect;
    Vec3 color;
    uint32_t cellsU, cellsV;  // Subdivision: strata of the light's surface
};

}  // namespace trazo
