// The material (SPEC §3 Material): its parameters listed once. The host struct (scene/scene.h Material), the
// kernels' MaterialData (shading/material.h), the host-to-kernel conversion (flatten/flatten.cpp) and the
// Material block's table rows (scene/scene_tables.cpp: reader, writer, checks, viewer widgets) are all
// generated from the two lists below, so a parameter the kernel reads is one row here plus its use. Plain
// macros and constants: kernel code includes this too.
#pragma once

#include <cstdint>

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
      "blend between lit colour (0) and reflection (1)")                                                            \
    X(int, fresnel, 0, uint32_t, fresnel, flagValue, "Fresnel", Flag, None,                                        \
      "1: the dielectric Fresnel factor splits reflection and transmission")                                        \
    X(float, refractionAngleDegrees, 0.0f, float, refractionHalfAngle, halfAngleRadians, "RefractionAngle",        \
      ConeAngle, Degrees, "full cone angle of glossy transmission in degrees; 0 = sharp refraction")                \
    X(float, dispersion, 0.0f, float, dispersion, sameValue, "Dispersion", Dispersion, None,                       \
      "20 / Abbe number: each colour channel refracts with its own index; 0 = none")                                \
    X(Vec3, scatteringDistance, (Vec3{0.0f, 0.0f, 0.0f}), Vec3, scatteringDistance, sameValue,                     \
      "ScatteringDistance", NonNegative, None, "mean free path per channel (subsurface scattering); 0 = off")

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

}  // namespace trazo
