// Which arrays of two flattened scenes differ, compared bytewise (the element types are plain structs
// without padding holes that flatten leaves unwritten: every one is value-initialised or fully assigned).
#include "flatten/array_mask.h"

#include <cstring>

namespace trazo {

namespace {

template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

template <typename T>
bool sameValue(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

}  // namespace

ArrayMask changedArrays(const SceneArrays& before, const SceneArrays& after, ArrayMask skip) {
    ArrayMask changed = kNoArrays;
#define TRAZO_X(T, name, ...)                                                                 \
    if (!(skip & maskOf(SceneArray::name)) && !sameBytes(before.name, after.name)) \
        changed |= maskOf(SceneArray::name);
    TRAZO_SCENE_ARRAYS(TRAZO_X)
#undef TRAZO_X
    const bool sameValues = sameValue(before.settings, after.settings) && before.features == after.features &&
                            before.traversalStackNeed == after.traversalStackNeed;
    if (!(skip & maskOf(SceneArray::values)) && !sameValues) changed |= maskOf(SceneArray::values);
    return changed;
}

std::string describeArrays(ArrayMask mask) {
    static const char* const kNames[] = {
#define TRAZO_X(T, name, ...) #name,
        TRAZO_SCENE_ARRAYS(TRAZO_X)
#undef TRAZO_X
        "values"};
    std::string s;
    for (uint32_t i = 0; i < uint32_t(SceneArray::count); ++i) {
        if (!(mask & (1u << i))) continue;
        if (!s.empty()) s += ' ';
        s += kNames[i];
    }
    return s.empty() ? "none" : s;
}

}  // namespace trazo
