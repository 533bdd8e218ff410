// Texture lookup (SPEC §3 Texture): bilinear between texel centres, repeat wrap, uv origin bottom-left.
// Texels of every texture live in one array; a texture is an offset and a size into it, so a texture used
// by several materials is stored once.
#pragma once

#include <cstdint>

#include "core/vec3.h"

namespace trazo {

struct TextureData {
    uint32_t offset;  // first texel in SceneView::texels; row 0 is the bottom row
    uint32_t width, height;
};

// Wraps an integer texel coordinate into [0, size).
TRAZO_HD uint32_t wrapTexel(int32_t i, uint32_t size) {
    const int32_t r = i % int32_t(size);
    return uint32_t(r < 0 ? r + int32_t(size) : r);
}

// Texel centres sit at ((i + ½)/width, (j + ½)/height); between them the four neighbours are blended.
TRAZO_HD Vec3 sampleTexture(const TextureData& tex, const Vec3* texels, float u, float v) {
    if (!(u == u) || !(v == v) || fabsf(u) > 1e6f || fabsf(v) > 1e6f) { u = 0.0f; v = 0.0f; }  // NaN, huge
    const float x = u * float(tex.width) - 0.5f;
    const float y = v * float(tex.height) - 0.5f;
    const float fx = floorf(x), fy = floorf(y);
    const float ax = x - fx, ay = y - fy;
    const uint32_t x0 = wrapTexel(int32_t(fx), tex.width), x1 = wrapTexel(int32_t(fx) + 1, tex.width);
    const uint32_t y0 = wrapTexel(int32_t(fy), tex.height), y1 = wrapTexel(int32_t(fy) + 1, tex.height);
    const Vec3* t = texels + tex.offset;
    const Vec3 bottom = t[y0 * tex.width + x0] * (1.0f - ax) + t[y0 * tex.width + x1] * ax;
    const Vec3 top = t[y1 * tex.width + x0] * (1.0f - ax) + t[y1 * tex.width + x1] * ax;
    return bottom * (1.0f - ay) + top * ay;
}

// Tangent-space normal map, OpenGL convention (+Y = green = the direction of increasing v): the texel's
// m = 2·rgb − 1 in the frame (tangent, bitangent, normal). All vectors unit; returns the unit normal.
TRAZO_HD Vec3 perturbNormal(Vec3 n, Vec3 tangent, Vec3 bitangent, Vec3 texel) {
    const Vec3 m = texel * 2.0f - Vec3(1.0f);
    const Vec3 perturbed = tangent * m.x + bitangent * m.y + n * m.z;
    const float len2 = dot(perturbed, perturbed);
    return len2 > 0.0f ? perturbed * (1.0f / sqrtf(len2)) : n;
}

}  // namespace trazo
