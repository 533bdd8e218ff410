// MaterialData, the material as kernels read it, generated from the material's list of parameters
// (shading/material_fields.h), with the conversions that list names and the feature bits a material implies.
#pragma once

#include <cstdint>

#include "core/feature_mask.h"
#include "core/hd.h"
#include "core/render_settings.h"
#include "core/vec3.h"
#include "shading/material_fields.h"

namespace trazo {

// The conversions a row names: the kernel takes the glossy cones as half-angles in radians, a flag as 0 or 1.
TRAZO_HD constexpr Vec3 sameValue(Vec3 v) { return v; }
TRAZO_HD constexpr float sameValue(float v) { return v; }
TRAZO_HD constexpr float halfAngleRadians(float fullDegrees) { return 0.5f * fullDegrees * (3.14159265358979f / 180.0f); }
TRAZO_HD constexpr uint32_t flagValue(int v) { return v != 0 ? 1u : 0u; }

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

// SPEC §6 Fresnel (b): a transparent Fresnel material reflects part of what it transmits (R′) whatever its Ks
// and ReflectionAmount, under the settings' reflection conditions (before any depth limit).
TRAZO_HD bool materialReflectsTransmitted(const MaterialData& m, const RenderSettings& s) {
    return m.fresnel != 0u && m.opacity < 1.0f && s.reflectionQuality >= 1 && s.reflectionSteps >= 1;
}

// SPEC §6: a material with a ScatteringDistance is a scattering medium below its surface.
TRAZO_HD bool materialScatters(const MaterialData& m) { return !isBlack(m.scatteringDistance); }

// The feature bits (core/feature_mask.h) a scene has because one of its objects uses this material.
inline FeatureMask materialFeatures(const MaterialData& m, const RenderSettings& s) {
    FeatureMask f = 0;
    const bool reflects = materialCanReflect(m, s) || materialReflectsTransmitted(m, s);
    if (reflects) f |= kFeatureReflection;
    if (m.opacity < 1.0f) f |= kFeatureRefraction;
    // Glossy cones, reflected or transmitted (SPEC §6), cycle their strata.
    if (reflects && m.reflectionHalfAngle > 0.0f) f |= kFeatureGlossy;
    if (m.opacity < 1.0f && m.refractionHalfAngle > 0.0f) f |= kFeatureGlossy;
    if (m.opacity < 1.0f && m.dispersion > 0.0f) f |= kFeatureDispersion;
    if (materialScatters(m)) f |= kFeatureSubsurface;
    if (!isBlack(m.emissive)) f |= kFeatureEmissive;
    if (materialHasTextures(m)) f |= kFeatureTextures;
    return f;
}

}  // namespace trazo
