// FeatureMask: what a scene uses, computed once at flatten time, so kernels can skip the rest.
#pragma once

#include <cstdint>
#include <string>

namespace trazo {

// X(bit, name): every feature, its mask bit (in list order) and the word messages and --stats print for it.
// The one list: the bits, their names and describeFeatures all come from it, so none can be left out.
#define TRAZO_FEATURES(X)                                                                                   \
    X(kFeaturePointLights, "point-lights")                                                                  \
    X(kFeatureAreaLights, "area-lights")                                                                    \
    X(kFeatureReflection, "reflection") /* a material reflects (mirror or glossy), ReflectionQuality ≥ 1 */ \
    X(kFeatureGlossy, "glossy")         /* a reflecting material has ReflectionAngle > 0 */                 \
    X(kFeatureRefraction, "refraction") /* a material has Opacity < 1 */                                    \
    X(kFeatureEmissive, "emissive")                                                                         \
    X(kFeatureIndirect, "indirect")     /* IndirectQuality ≥ 1 and ColorBleeding > 0 */                     \
    X(kFeatureTextures, "textures")                                                                         \
    X(kFeatureMeshes, "meshes")                                                                             \
    X(kFeatureCsg, "csg")                                                                                   \
    X(kFeatureDispersion, "dispersion") /* a material with Opacity < 1 has Dispersion > 0 (SPEC §6) */      \
    X(kFeatureSubsurface, "subsurface") /* a material has a ScatteringDistance (SPEC §6) */                  \
    X(kFeatureEnvironmentMap, "environment-map") /* SceneSettings EnvironmentMap (SPEC §7) */

// Bit positions, in list order.
enum FeatureBit : uint32_t {
#define TRAZO_X(bit, name) bit##Bit,
    TRAZO_FEATURES(TRAZO_X)
#undef TRAZO_X
    kFeatureCount
};

enum Feature : uint32_t {
#define TRAZO_X(bit, name) bit = 1u << bit##Bit,
    TRAZO_FEATURES(TRAZO_X)
#undef TRAZO_X
};

using FeatureMask = uint32_t;

struct FeatureName {
    Feature bit;
    const char* name;
};
constexpr FeatureName kFeatureNames[kFeatureCount] = {
#define TRAZO_X(bit, name) {bit, name},
    TRAZO_FEATURES(TRAZO_X)
#undef TRAZO_X
};

// "area-lights reflection …" for messages and --stats.
std::string describeFeatures(FeatureMask mask);

}  // namespace trazo
