// FeatureMask: what a scene uses, computed once at flatten time, so kernels can skip the rest.
#pragma once

#include <cstdint>
#include <string>

namespace trazo {

enum Feature : uint32_t {
    kFeaturePointLights = 1u << 0,
    kFeatureAreaLights = 1u << 1,
    kFeatureReflection = 1u << 2,  // some material reflects (mirror or glossy) and ReflectionQuality ≥ 1
    kFeatureGlossy = 1u << 3,      // some reflecting material has ReflectionAngle > 0
    kFeatureRefraction = 1u << 4,  // some material has Opacity < 1
    kFeatureEmissive = 1u << 5,
    kFeatureIndirect = 1u << 6,    // IndirectQuality ≥ 1 and ColorBleeding > 0
    kFeatureTextures = 1u << 7,
    kFeatureMeshes = 1u << 8,
    kFeatureCsg = 1u << 9,
};

using FeatureMask = uint32_t;

// "area-lights reflection …" for messages and --stats.
std::string describeFeatures(FeatureMask mask);

}  // namespace trazo
