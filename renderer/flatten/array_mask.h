// ArrayMask: a set of the flattened scene's arrays (one bit per TRAZO_SCENE_ARRAYS entry, plus one for the
// plain values beside them), what an edit changed and what Backend::upload(arrays, changed) re-sends. Host code.
#pragma once

#include <cstdint>
#include <string>

#include "flatten/scene_arrays.h"

namespace trazo {

// The arrays of TRAZO_SCENE_ARRAYS in list order (SceneArray::spheres, ..., SceneArray::topNodes), then
// `values`: settings, features and traversalStackNeed, the scene's fields that are not arrays.
enum class SceneArray : uint32_t {
#define TRAZO_X(T, name, ...) name,
    TRAZO_SCENE_ARRAYS(TRAZO_X)
#undef TRAZO_X
    values,
    count
};

using ArrayMask = uint32_t;
static_assert(uint32_t(SceneArray::count) <= 32, "ArrayMask holds one bit per array");

constexpr ArrayMask maskOf(SceneArray a) { return 1u << uint32_t(a); }
constexpr ArrayMask kNoArrays = 0;
constexpr ArrayMask kAllArrays = (1u << uint32_t(SceneArray::count)) - 1u;
// What only a mesh's BVH build writes; flatten() can reuse them from an earlier result.
constexpr ArrayMask kMeshArrays = maskOf(SceneArray::meshes) | maskOf(SceneArray::meshNodes) |
                                  maskOf(SceneArray::triangles) | maskOf(SceneArray::triangleCorners);

// The arrays (and values) whose bytes differ between `before` and `after`; those in `skip` are not
// compared and never reported (arrays the caller knows are equal, e.g. flatten()'s reused mesh arrays).
ArrayMask changedArrays(const SceneArrays& before, const SceneArrays& after, ArrayMask skip = kNoArrays);

// The arrays' names in list order, separated by spaces ("spheres objects topNodes"); "none" for an empty mask.
std::string describeArrays(ArrayMask mask);

}  // namespace trazo
