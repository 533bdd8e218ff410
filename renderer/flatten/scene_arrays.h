// SceneArrays: the owning host copy of the flattened scene (what Backend::upload takes), and hostView(), the
// SceneView of host-resident arrays.
#pragma once

#include <cstdint>
#include <vector>

#include "accel/wide_bvh_node.h"
#include "core/vec3.h"
#include "lights/area_light.h"
#include "lights/environment.h"
#include "lights/point_light.h"
#include "lights/rectangle.h"
#include "objects/scene_view.h"
#include "objects/visit_object.h"  // every object kind's header
#include "shading/material.h"
#include "shading/texture.h"

namespace trazo {

struct SceneArrays {
#define TRAZO_X(T, name, ...) std::vector<T> name;
    TRAZO_SCENE_ARRAYS(TRAZO_X)
#undef TRAZO_X
    RenderSettings settings{};
    FeatureMask features = 0;
    // Entries of the traversal stack the two BVH levels need together (the top level's need plus the
    // neediest mesh's): a backend whose kernels hold fewer refuses the scene at upload.
    uint32_t traversalStackNeed = 0;
};

template <typename T>
ArrayView<T> viewOf(const std::vector<T>& v) {
    return ArrayView<T>{v.data(), (uint32_t)v.size()};
}

// A view of host-resident arrays (the CPU backend renders straight from them).
inline SceneView hostView(const SceneArrays& a) {
    SceneView view{};
#define TRAZO_X(T, name, ...) view.name = viewOf(a.name);
    TRAZO_SCENE_ARRAYS(TRAZO_X)
#undef TRAZO_X
    view.settings = a.settings;
    view.features = a.features;
    return view;
}

}  // namespace trazo
