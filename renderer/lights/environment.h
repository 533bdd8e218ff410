// The environment of SPEC §7 as kernels read it (SceneView::environment, at most one element): the radiance
// BackgroundColor ⊙ M(d) of a ray that leaves the scene, M the bilinear texel of an equirectangular map (1
// without one), as a light sampled in proportion to its brightness. The tables come from
// flatten/environment_tables.h. Host and device; templated on the scene (SceneView, objects/, stands above lights/).
#pragma once

#include <cstdint>

#include "core/sin_cos.h"
#include "core/vec3.h"
#include "lights/light_sample.h"
#include "shading/texture.h"

namespace trazo {

struct EnvironmentData {
    Vec3 background;                 // BackgroundColor: multiplies M(d)
    int32_t texture;                 // into SceneView::textures; -1: no map, M = 1
    float cosRotation, sinRotation;  // EnvironmentRotation, about +Y
    // Into SceneView::environmentCdf: the marginal CDF over the grid's rows (rows + 1 floats, top row first), then
    // each row's CDF over its columns (cols + 1 floats each). A CDF c[0..n] has c[0] = 0 and is non-decreasing;
    // cell i's share is (c[i+1] − c[i]) / c[n], positive wherever the map's radiance is not 0 somewhere in the cell.
    uint32_t cdfOffset;
    uint32_t cols, rows;  // the sampling grid over (u, v); 0 without a map (uniform directions)
    // ∫ luminance(|BackgroundColor ⊙ M(ω)|) dω over the sphere (radiance × steradians; Rec. 709 luminance),
    // 4π·luminance(|BackgroundColor|) without a map: a measure of the whole environment's brightness for choosing
    // between it and other lights (times π·r², r the scene's bounding radius, it is the flux pbrt gives an
    // infinite light). Always > 0: an environment that is black everywhere is not stored.
    float power;
};

constexpr float kEnvironmentPi = 3.14159265358979f;

struct EnvironmentUv {
    float u, v;  // u ∈ [0, 1] around +Y, v ∈ [0, 1] from +Y (v = 0, the map's top row) to −Y
};

// d′: d turned by −EnvironmentRotation about +Y (SPEC §7), where the map is read.
TRAZO_HD Vec3 environmentLocal(const EnvironmentData& env, Vec3 d) {
    return {env.cosRotation * d.x - env.sinRotation * d.z, d.y, env.sinRotation * d.x + env.cosRotation * d.z};
}

// SPEC §7: u = 0.5 + atan2(x′, −z′)/(2π), v = acos(clamp(y′, −1, 1))/π. A NaN direction still reads inside the map.
TRAZO_HD EnvironmentUv environmentUv(const EnvironmentData& env, Vec3 d) {
    const Vec3 l = environmentLocal(env, d);
    float u = 0.5f + atan2f(l.x, -l.z) * (0.5f / kEnvironmentPi);
    float v = acosf(minOf(maxOf(l.y, -1.0f), 1.0f)) * (1.0f / kEnvironmentPi);
    if (!(u >= 0.0f && u <= 1.0f)) u = 0.5f;
    if (!(v >= 0.0f && v <= 1.0f)) v = 0.5f;
    return {u, v};
}

// The unit direction whose map coordinates are (u, v): the inverse of environmentUv, turned back by +rotation.
TRAZO_HD Vec3 environmentDirection(const EnvironmentData& env, float u, float v) {
    float sinTheta, cosTheta, sinU, cosU;
    sinCos(kEnvironmentPi * v, sinTheta, cosTheta);
    sinCos(2.0f * kEnvironmentPi * u, sinU, cosU);  // φ = 2π(u − ½): sin φ = −sin 2πu, cos φ = −cos 2πu
    const float x = -sinTheta * sinU, z = sinTheta * cosU;  // x′ = sin θ sin φ, z′ = −sin θ cos φ
    return {env.cosRotation * x + env.sinRotation * z, cosTheta, env.cosRotation * z - env.sinRotation * x};
}

// Clamps an integer texel or cell coordinate into [0, size).
TRAZO_HD uint32_t clampIndex(int32_t i, uint32_t size) {
    return i < 0 ? 0u : (uint32_t(i) >= size ? size - 1 : uint32_t(i));
}

// M at (u, v): bilinear between texel centres, wrapping in u and clamped in v (the top and bottom rows reach the
// poles). The map's row r from the top is stored row height − 1 − r (TextureData: row 0 is the bottom).
TRAZO_HD Vec3 environmentTexel(const TextureData& tex, const Vec3* texels, float u, float v) {
    const float x = u * float(tex.width) - 0.5f, y = v * float(tex.height) - 0.5f;
    const float fx = floorf(x), fy = floorf(y);
    const float ax = x - fx, ay = y - fy;
    const uint32_t x0 = wrapTexel(int32_t(fx), tex.width), x1 = wrapTexel(int32_t(fx) + 1, tex.width);
    const uint32_t r0 = clampIndex(int32_t(fy), tex.height), r1 = clampIndex(int32_t(fy) + 1, tex.height);
    const Vec3* upper = texels + tex.offset + size_t(tex.height - 1 - r0) * tex.width;
    const Vec3* lower = texels + tex.offset + size_t(tex.height - 1 - r1) * tex.width;
    const Vec3 top = upper[x0] * (1.0f - ax) + upper[x1] * ax;
    const Vec3 bottom = lower[x0] * (1.0f - ax) + lower[x1] * ax;
    return top * (1.0f - ay) + bottom * ay;
}

// The radiance arriving from unit direction d: BackgroundColor ⊙ M(d); 0 without an environment.
template <class Scene>
TRAZO_HD Vec3 environmentRadiance(const Scene& scene, Vec3 d) {
    if (scene.environment.count == 0) return Vec3(0.0f);
    const EnvironmentData& env = scene.environment[0];
    if (env.texture < 0) return env.background;
    const EnvironmentUv uv = environmentUv(env, d);
    return env.background * environmentTexel(scene.textures[uint32_t(env.texture)], scene.texels.data, uv.u, uv.v);
}

// The cell of a CDF c[0..n] (see EnvironmentData::cdfOffset) that holds t, 0 ≤ t < c[n]: the largest i < n with
// c[i] ≤ t, so never a cell of share 0. At most 32 halvings (n < 2^32).
TRAZO_HD uint32_t findCdfCell(const float* cdf, uint32_t n, float t) {
    uint32_t lo = 0, hi = n;  // c[lo] ≤ t < c[hi]
    for (int k = 0; k < 32 && hi - lo > 1; ++k) {
        const uint32_t mid = lo + (hi - lo) / 2;
        if (cdf[mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

// Cell i's density over [0, 1] (n cells of width 1/n): n × its share. 0 when the CDF is all 0.
TRAZO_HD float cdfDensity(const float* cdf, uint32_t n, uint32_t i) {
    const float total = cdf[n];
    return total > 0.0f ? (cdf[i + 1] - cdf[i]) / total * float(n) : 0.0f;
}

struct CdfDraw {
    uint32_t cell;
    float offset;   // within the cell, [0, 1)
    float density;  // cdfDensity of the cell
};

// A cell drawn by the CDF (c[n] > 0) from u ∈ [0, 1), and where u falls inside it.
TRAZO_HD CdfDraw drawFromCdf(const float* cdf, uint32_t n, float u) {
    const float total = cdf[n];
    const float t = minOf(maxOf(u * total, 0.0f), bitsFloat(floatBits(total) - 1u));  // below c[n]
    const uint32_t i = findCdfCell(cdf, n, t);
    const float offset = (t - cdf[i]) / (cdf[i + 1] - cdf[i]);
    return {i, minOf(offset, 0.99999994f), cdfDensity(cdf, n, i)};
}

// The solid-angle density of a (u, v) density p over the map: dω = 2π² sin θ du dv. sin θ is read from the
// direction itself (|(x, z)|, which the rotation keeps), so sampleEnvironment's pdf and pdfEnvironment's agree.
TRAZO_HD float environmentSolidAnglePdf(float uvDensity, Vec3 wi) {
    const float sinTheta = sqrtf(wi.x * wi.x + wi.z * wi.z);
    if (!(sinTheta > 0.0f)) return 0.0f;  // a pole: a set of measure 0
    return uvDensity / (2.0f * kEnvironmentPi * kEnvironmentPi * sinTheta);
}

// A direction towards the environment from (u1, u2) ∈ [0, 1)²: uniform on the sphere without a map; with one, a
// grid row by the marginal CDF (u2), a column by that row's CDF (u1), a uniform (u, v) inside the cell.
template <class Scene>
TRAZO_HD LightSample sampleEnvironment(const Scene& scene, float u1, float u2) {
    if (scene.environment.count == 0) return noLightSample();
    const EnvironmentData& env = scene.environment[0];
    if (env.rows == 0) {
        const float y = 1.0f - 2.0f * u1, r = sqrtf(maxOf(0.0f, 1.0f - y * y));
        float s, c;
        sinCos(2.0f * kEnvironmentPi * u2, s, c);
        return LightSample{Vec3(r * c, y, r * s), env.background, 1.0f / (4.0f * kEnvironmentPi), INFINITY, false};
    }
    const float* marginal = scene.environmentCdf.data + env.cdfOffset;
    if (!(marginal[env.rows] > 0.0f)) return noLightSample();
    const CdfDraw row = drawFromCdf(marginal, env.rows, u2);
    const CdfDraw col = drawFromCdf(marginal + (env.rows + 1) + row.cell * (env.cols + 1), env.cols, u1);
    const float u = (float(col.cell) + col.offset) / float(env.cols);
    const float v = (float(row.cell) + row.offset) / float(env.rows);
    const Vec3 wi = environmentDirection(env, u, v);
    const float pdf = environmentSolidAnglePdf(row.density * col.density, wi);
    if (!(pdf > 0.0f)) return noLightSample();
    return LightSample{wi, environmentRadiance(scene, wi), pdf, INFINITY, false};
}

// The density with which sampleEnvironment gives unit direction wi (solid angle); 0 without an environment.
template <class Scene>
TRAZO_HD float pdfEnvironment(const Scene& scene, Vec3 wi) {
    if (scene.environment.count == 0) return 0.0f;
    const EnvironmentData& env = scene.environment[0];
    if (env.rows == 0) return 1.0f / (4.0f * kEnvironmentPi);
    const EnvironmentUv uv = environmentUv(env, wi);
    const uint32_t col = clampIndex(int32_t(uv.u * float(env.cols)), env.cols);
    const uint32_t row = clampIndex(int32_t(uv.v * float(env.rows)), env.rows);
    const float* marginal = scene.environmentCdf.data + env.cdfOffset;
    const float rowDensity = cdfDensity(marginal, env.rows, row);
    if (!(rowDensity > 0.0f)) return 0.0f;
    const float colDensity = cdfDensity(marginal + (env.rows + 1) + row * (env.cols + 1), env.cols, col);
    return environmentSolidAnglePdf(rowDensity * colDensity, wi);
}

}  // namespace trazo
