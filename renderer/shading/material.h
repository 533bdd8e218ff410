// The material (SPEC §3 Material): its parameters listed once, and MaterialData, the form kernels read.
// The host struct (scene/scene.h Material), MaterialData, the host-to-kernel conversion (device/flatten.cpp)
// and the Material block's table rows (scene/scene_tables.cpp: reader, writer, checks, viewer widgets) are
// all generated from the two lists below, so a parameter the kernel reads is one row here plus its use.
#pragma once

#include <cstdint>

#include "core/feature_mask.h"
#include "core/hd.h"
#include "core/vec3.h"
#include "objects/scene_view.h"

namespace trazo {

// X(host type, host name, default, kernel type, kernel name, to kernel, keyword, check, unit, doc); `check` and
// `unit` name a ValueCheck and a ValueUnit (scene/param_check.h). TEXTURE_SLOTS() marks where the texture
// parameters (TRAZO_TEXTURE_SLOTS) sit in the block's table; both structs keep the slots in one array.
#define TRAZO_MATERIAL_FIELDS(X, TEXTURE_SLOTS)                                                                    \
    X(Vec3, diffuseColor, (Vec3{0.9f, 0.9f, 0.9f}), Vec3, diffuse, sameValue, "DiffuseColor", Colour, Color,       \
      "diffuse colour (Oren–Nayar)")                                                                                \
    X(Vec3, specularColor, (Vec3{0.8f, 0.8f, 0.8f}), Vec3, specular, sameValue, "SpecularColor", Colour, Color,    \
      "specular colour (Cook–Torrance); also tints reflections")                                                    \
    X(Vec3, emissiveColor, (Vec3{0.0f, 0.0f, 0.0f}), Vec3, emissive, sameValue, "EmissiveColor", Colour, Color,    \
      "colour emitted without lighting")                                                                            \
    TEXTURE_SLOTS()                                                                                                 \
    X(float, roughness, 0.5f, float, roughness, sameValue, "Roughness", NonNegative, None, "0 polished … 1 rough") \
    X(float, opacity, 1.0f, float, opacity, sameValue, "Opacity", UnitInterval, None,                              \
      "1 opaque … 0 fully transparent")                                                                             \
    X(float, refractionIndex, 1.0f, float, refractionIndex, sameValue, "RefractionIndex", Positive, None,          \
      "index of refraction")                                                                                        \
    X(float, reflectionAngleDegrees, 0.0f, float, reflectionHalfAngle, halfAngleRadians, "ReflectionAngle",        \
      ConeAngle, Degrees, "full cone angle of glossy reflections in degrees; 0 = mirror")                           \
    X(float, reflectionAmount, 0.0f, float, reflectionAmount, sameValue, "ReflectionAmount", UnitInterval, None,   \
      "blend between lit colour (0) and reflection (1)")

// X(slot, keyword, doc): the material's textures, each an index into the scene's textures or kNoTexture.
#define TRAZO_TEXTURE_SLOTS(X)                                               \
    X(kDiffuseTexture, "DiffuseTexture", "texture multiplying DiffuseColor")    \
    X(kSpecularTexture, "SpecularTexture", "texture multiplying SpecularColor") \
    X(kEmissiveTexture, "EmissiveTexture", "texture multiplying EmissiveColor") \
    X(kNormalTexture, "NormalTexture", "tangent-space normal map (meshes only)")

enum TextureSlot : int {
#define TRAZO_X(slot, ...) slot,
    TRAZO_TEXTURE_SLOTS(TRAZO_X)
#undef TRAZO_X
    kTextureSlotCount
};
constexpr int32_t kNoTexture = -1;

// The conversions a row names: the kernel takes the glossy cone as its half-angle in radians.
TRAZO_HD constexpr Vec3 sameValue(Vec3 v) { return v; }
TRAZO_HD constexpr float sameValue(float v) { return v; }
TRAZO_HD constexpr float halfAngleRadians(float fullDegrees) { return 0.5f * fullDegrees * (3.14159265358979f / 180.0f); }

struct MaterialData {
#define TRAZO_X(HostType, hostName, fallback, Type, name, ...) Type name;
#define TRAZO_NO_SLOTS()
    TRAZO_MATERIAL_FIELDS(TRAZO_X, TRAZO_NO_SLOTS)
#undef TRAZO_NO_SLOTS
#undef TRAZO_X
    int32_t textures[kTextureSlotCount];  // by TextureSlot; into SceneView::textures, kNoTexture = none
};

// Whether any of the material's textures needs texture coordinates.
TRAZO_HD bool materialHasTextures(const MaterialData& m) {
    for (int s = 0; s < kTextureSlotCount; ++s)
        if (m.textures[s] >= 0) return true;
    return false;
}

// Whether the material reflects at all under these settings (a mirror or glossy lobe, before any depth limit).
TRAZO_HD bool materialCanReflect(const MaterialData& m, const RenderSettings& s) {
    return !isBlack(m.specular) && m.reflectionAmount > 0.0f && m.opacity > 0.0f && s.reflectionQuality >= 1 &&
           s.reflectionSteps >= 1;
}

// The feature bits (core/feature_mask.h) a scene has because one of its objects uses this material.
inline FeatureMask materialFeatures(const MaterialData& m, const RenderSettings& s) {
    FeatureMask f = 0;
    const bool reflects = materialCanReflect(m, s);
    if (reflects) f |= kFeatureReflection;
    if (reflects && m.reflectionHalfAngle > 0.0f) f |= kFeatureGlossy;
    if (m.opacity < 1.0f) f |= kFeatureRefraction;
    if (!isBlack(m.emissive)) f |= kFeatureEmissive;
    if (materialHasTextures(m)) f |= kFeatureTextures;
    return f;
}

}  // namespace trazo
