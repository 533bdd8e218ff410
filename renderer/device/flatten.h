// flatten(): host Scene -> SceneArrays (world-space shapes and meshes, textures, the two BVH levels,
// material indices, feature mask).
#pragma once

#include "device/scene_arrays.h"
#include "scene/scene.h"

namespace trazo {

struct FlattenResult {
    SceneArrays arrays;
    // What of the scene is read but not drawn as written (textures on an object without texture coordinates),
    // at the line of its block; the rest of the scene renders.
    Diagnostics warnings;
};

FlattenResult flatten(const Scene& scene);

// u and v axes of an area light's rectangle (SPEC §3 AreaLight), unit length, before Width/Height.
void areaLightAxes(Vec3 normal, float rollAngle, Vec3& u, Vec3& v);

}  // namespace trazo
