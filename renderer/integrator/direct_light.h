// Direct(P) of SPEC §5: point lights with hard shadows, area lights by a block of jittered cells per pass.
#pragma once

#include "core/rng.h"
#include "integrator/strata.h"
#include "integrator/scene_intersect.h"
#include "integrator/shading_point.h"
#include "shading/cook_torrance.h"
#include "shading/material.h"
#include "shading/oren_nayar.h"
// Host code that g++ compiles for x86-64 (not the device, nor nvcc's host pass, which renders nothing): an area
// light's shadow rays traced in packets (occluded_packet.h).
#if !TRAZO_DEVICE_PATHS && !defined(__CUDACC__) && defined(__SSE2__)
#define TRAZO_SHADOW_PACKETS 1
#include "integrator/occluded_packet.h"
#else
#define TRAZO_SHADOW_PACKETS 0
#endif

namespace trazo {

// The material's Shade of SPEC §5 at one shading point. On the host a black lobe is never evaluated (a matte
// surface pays no Cook–Torrance; σ = 0 no Oren–Nayar azimuth) and what depends only on the viewer is computed
// once per point. The device evaluates both lobes per sample without branches: fewer live values, and the
// registers are what limit a GPU thread (ptxas, sm_90: 12 of the 16 variants at or below 9b68041's count).
struct PointBrdf {
    const ShadingPoint& sp;
    const MaterialData& m;
    bool hasDiffuse, hasSpecular;
#if !TRAZO_DEVICE_PATHS
    OrenNayarView diffuseView;
#endif

    TRAZO_HD PointBrdf(const ShadingPoint& spIn, const MaterialData& mIn)
        : sp(spIn), m(mIn), hasDiffuse(!isBlack(mIn.diffuse)), hasSpecular(!isBlack(mIn.specular)) {
#if !TRAZO_DEVICE_PATHS
        diffuseView = orenNayarView(sp.n, sp.v, m.roughness);
#endif
    }

    TRAZO_HD bool reflects() const { return (hasDiffuse || hasSpecular) && dot(sp.n, sp.v) > 0.0f; }
    // Kd·ON(N, L, V, σ) + Ks·CT(N, L, V, σ); N·L > 0 and N·V > 0 assumed.
    TRAZO_HD Vec3 eval(Vec3 l) const {
        Vec3 f(0.0f);
#if !TRAZO_DEVICE_PATHS
        if (hasDiffuse) f = m.diffuse * evalOrenNayar(diffuseView, sp.n, l);
        if (hasSpecular) f += m.specular * evalCookTorrance(sp.n, l, sp.v, m.roughness);
#else  // both lobes, branch-free: a black one adds 0
        f = m.diffuse * evalOrenNayar(sp.n, l, sp.v, m.roughness) +
            m.specular * evalCookTorrance(sp.n, l, sp.v, m.roughness);
#endif
        return f;
    }
};

// PointBrdf(sp, m).reflects(), without the view it computes.
TRAZO_HD bool reflectsLight(const ShadingPoint& sp, const MaterialData& m) {
    return (!isBlack(m.diffuse) || !isBlack(m.specular)) && dot(sp.n, sp.v) > 0.0f;
}

// The shadow ray from the shading point towards a light sample X: l the unit vector to X, leaving from origin
// over (0, |X − origin|); false where Shade is 0 without one (X at the point, or not above its shading normal).
TRAZO_HD bool aimShadowRay(const ShadingPoint& sp, Vec3 x, Vec3& l, Vec3& origin) {
    Vec3 toLight = x - sp.p;
    const float dist = length(toLight);
    if (!(dist > 0.0f)) return false;
    l = toLight / dist;
    if (dot(sp.n, l) <= 0.0f) return false;
    origin = sp.rayOrigin(l);
    return true;
}

// One light sample X seen from the shading point: visible ⇒ Shade(P, L, C) = C ⊙ brdf(L). Counts the
// shadow ray.
TRAZO_HD Vec3 shadeFromPoint(const SceneView& scene, const ShadingPoint& sp, const PointBrdf& brdf, Vec3 x,
                             Vec3 color, uint32_t& rays) {
    Vec3 l, origin;
    if (!aimShadowRay(sp, x, l, origin)) return Vec3(0.0f);  // Shade would be 0: no shadow ray
    ++rays;
    if (occluded(scene, Ray{origin, l}, length(x - origin))) return Vec3(0.0f);
    return color * brdf.eval(l);
}

// The jittered point of cell s of the light's grid (two draws of rng, u first).
TRAZO_HD Vec3 cellPoint(const AreaLightData& light, uint32_t s, SampleStream& rng) {
    const float su = (float(s % light.cellsU) + rng.next()) / float(light.cellsU);
    const float sv = (float(s / light.cellsU) + rng.next()) / float(light.cellsV);
    return light.rect.center + light.rect.halfU * (2.0f * su - 1.0f) + light.rect.halfV * (2.0f * sv - 1.0f);
}

#if TRAZO_SHADOW_PACKETS
// Host: blocks of fewer cells take shadeFromPoint ray by ray (a packet's set-up costs more than it saves).
constexpr uint32_t kMinShadowPacket = 4;

// Host: brdf.eval(l) for the rays of `lanes` in group g of the packet, in SIMD lanes: PointBrdf::eval with
// evalOrenNayar and evalCookTorrance operation for operation (minOf(a, b) is a < b ? a : b, maxOf a > b ? a : b),
// expf lane by lane (libm's, as the scalar code calls it).
inline void evalBrdfLanes(const PointBrdf& brdf, const RayPacket& packet, int g, uint64_t lanes, float* fx,
                          float* fy, float* fz) {
    using namespace packet_detail;
    const int o = g * kLanes;
    const V3 l = {load(packet.dx + o), load(packet.dy + o), load(packet.dz + o)};
    const Vec3 n = brdf.sp.n;
    V3 f = {splat(0.0f), splat(0.0f), splat(0.0f)};
    if (brdf.hasDiffuse) {
        const OrenNayarView& w = brdf.diffuseView;
        const LaneF nl = dot(n, l);
        const LaneF cosL = nl < 1.0f ? nl : splat(1.0f);
        LaneF on = cosL * w.a;
        if (w.b != 0.0f) {
            const LaneF lvt = dot(w.vt, l);
            const LaneF azimuth = 0.0f > lvt ? splat(0.0f) : lvt;
            const LaneF slope = cosL <= w.cosV ? (cosL / w.cosV) * w.sinV : splat(w.sinV);
            on = cosL * w.a + w.b * azimuth * slope;
        }
        const Vec3 d = brdf.m.diffuse;
        f = {d.x * on, d.y * on, d.z * on};
    }
    if (brdf.hasSpecular) {
        const Vec3 v = brdf.sp.v;
        const float m = maxOf(brdf.m.roughness, 0.01f);
        const V3 sum = {l.x + v.x, l.y + v.y, l.z + v.z};
        const LaneF inv = 1.0f / sqrt(dot(sum, sum));
        const V3 h = {sum.x * inv, sum.y * inv, sum.z * inv};
        const LaneF nh0 = dot(n, h);
        const LaneF nh = nh0 < 1.0f ? nh0 : splat(1.0f);
        const float nv = dot(n, v);
        const LaneF nl = dot(n, l);
        const LaneF vh = dot(v, h);
        const LaneI zero = (nh <= 0.0f) | (vh <= 0.0f);
        const LaneF nh2 = nh * nh;
        const LaneF tan2 = (1.0f - nh2) / nh2;
        const float m2 = m * m;
        const LaneF exponent = -tan2 / m2;
        LaneF e = splat(0.0f);
        for (uint64_t left = lanes & ~bits(zero); left; left &= left - 1) {
            const int i = __builtin_ctzll(left);
            e[i] = expf(exponent[i]);
        }
        const LaneF piD = e / (m2 * nh2 * nh2);
        const LaneF nearer = nv < nl ? splat(nv) : nl;
        const LaneF g2 = 2.0f * nh * nearer / vh;
        const LaneF gTerm = 1.0f < g2 ? splat(1.0f) : g2;
        const LaneF ct = zero ? splat(0.0f) : piD * gTerm / (4.0f * nv);
        const Vec3 sp = brdf.m.specular;
        f = {f.x + sp.x * ct, f.y + sp.y * ct, f.z + sp.z * ct};
    }
    std::memcpy(fx + o, &f.x, sizeof f.x);
    std::memcpy(fy + o, &f.y, sizeof f.y);
    std::memcpy(fz + o, &f.z, sizeof f.z);
}

// Host: the sum of shadeFromPoint over the block's cells, kPacketRays cells at a time: the rng draws, light
// points and shadow rays in SIMD lanes (aimShadowRays), the rays traced together (occludedPacket, one packet
// per origin), the visible cells' BRDF in lanes (evalBrdfLanes), and their colours summed in cell order. The
// same draws, rays and sum as the loop over shadeFromPoint, bit for bit.
inline Vec3 shadeCellsTogether(const SceneView& scene, const ShadingPoint& sp, const PointBrdf& brdf,
                               const AreaLightData& light, const StrataBlock& cells, SampleStream& rng,
                               uint32_t& rays) {
    Vec3 lightSum(0.0f);
    const Vec3 below = bumpedOrigin(sp.p, -(sp.ng * sp.offset));  // rayOrigin towards −ng
    RayPacket packet;
    alignas(64) float column[kPacketRays], row[kPacketRays];  // of each cell in the light's grid
    const uint32_t stepU = cells.blocks % light.cellsU, stepV = cells.blocks / light.cellsU;
    alignas(64) float fx[kPacketRays], fy[kPacketRays], fz[kPacketRays];  // brdf.eval of the visible cells
    for (uint32_t start = 0; start < cells.size; start += kPacketRays) {
        const uint32_t count = cells.size - start < kPacketRays ? cells.size - start : kPacketRays;
        // Strata step by cells.blocks: column and row of stratum(start + k) without a division per cell.
        uint32_t u = cells.stratum(start) % light.cellsU, v = cells.stratum(start) / light.cellsU;
        for (uint32_t k = 0; k < count; ++k) {
            column[k] = float(u);
            row[k] = float(v);
            u += stepU;
            v += stepV;
            if (u >= light.cellsU) u -= light.cellsU, ++v;
        }
        for (uint32_t k = count; k < (uint32_t)kPacketRays; ++k) column[k] = row[k] = 0.0f;
        const AimedRays aimed = aimShadowRays(light.rect, light.cellsU, light.cellsV, column, row, rng.key,
                                              rng.dimension, sp.p, sp.n, sp.ng, sp.above, below, packet);
        rng.dimension += 2u * count;  // cellPoint's two draws per cell, taken in the lanes
        const uint64_t traced = aimed.traced & (count == (uint32_t)kPacketRays ? ~0ull : (1ull << count) - 1);
        rays += (uint32_t)__builtin_popcountll(traced);
        uint64_t blocked = occludedPacket(scene, sp.above, packet, traced & ~aimed.fromBelow);
        if (traced & aimed.fromBelow) blocked |= occludedPacket(scene, below, packet, traced & aimed.fromBelow);
        const uint64_t visible = traced & ~blocked;
        for (int g = 0; g < packet_detail::kGroups; ++g) {
            const uint64_t lanes = (visible >> (g * packet_detail::kLanes)) & packet_detail::kGroupBits;
            if (lanes) evalBrdfLanes(brdf, packet, g, lanes, fx, fy, fz);
        }
        for (uint32_t k = 0; k < count; ++k)
            lightSum += visible & (1ull << k) ? light.color * Vec3(fx[k], fy[k], fz[k]) : Vec3(0.0f);
    }
    return lightSum;
}

// Host: directLight<F> for F without area lights (point lights only) at each point of `at` (bit i: points[i]
// with materials[i]) into out[i]: for each light in turn, the points' shadow rays traced together, each from
// its own origin (occludedPacket). The same rays and sums, bit for bit.
inline void directPointLightsTogether(const SceneView& scene, const ShadingPoint* points,
                                      const MaterialData* materials, uint64_t at, Vec3* out, uint32_t& rays) {
    uint64_t reflecting = 0;
    for (uint64_t left = at; left; left &= left - 1) {
        const int i = __builtin_ctzll(left);
        out[i] = Vec3(0.0f);
        if (reflectsLight(points[i], materials[i])) reflecting |= 1ull << i;
    }
    if (!reflecting) return;
    RayPacket packet;
    RayOrigins origins;
    const int lanesUsed = (64 - __builtin_clzll(reflecting) + packet_detail::kLanes - 1) / packet_detail::kLanes *
                          packet_detail::kLanes;
    for (int i = lanesUsed; i < kPacketRays; ++i) {  // never traced, but read whole by the packet's set-up
        origins.ox[i] = origins.oy[i] = origins.oz[i] = 0.0f;
        packet.dx[i] = packet.dy[i] = packet.tMax[i] = 0.0f;
        packet.dz[i] = 1.0f;
    }
    for (uint32_t k = 0; k < scene.pointLights.count; ++k) {
        const PointLightData& light = scene.pointLights[k];
        uint64_t aimed = 0;
        for (int i = 0; i < lanesUsed; ++i) {
            Vec3 l(0.0f, 0.0f, 1.0f), origin(0.0f);  // lanes not aimed are never traced
            float tMax = 0.0f;
            if ((reflecting >> i & 1u) && aimShadowRay(points[i], light.position, l, origin)) {
                tMax = length(light.position - origin);
                aimed |= 1ull << i;
            }
            origins.ox[i] = origin.x, origins.oy[i] = origin.y, origins.oz[i] = origin.z;
            packet.dx[i] = l.x, packet.dy[i] = l.y, packet.dz[i] = l.z;
            packet.tMax[i] = tMax;
        }
        rays += (uint32_t)__builtin_popcountll(aimed);
        const uint64_t visible = aimed & ~occludedPacket(scene, origins, packet, aimed);
        for (uint64_t left = reflecting; left; left &= left - 1) {
            const int i = __builtin_ctzll(left);
            const Vec3 l(packet.dx[i], packet.dy[i], packet.dz[i]);
            out[i] += visible >> i & 1u ? light.color * PointBrdf(points[i], materials[i]).eval(l) : Vec3(0.0f);
        }
    }
}
#endif

// F: the scene's specialised feature bits (sample_variants.h); without kFeatureAreaLights the area-light
// loop is compiled out. lightBlock: the StrataBlocks target for the area lights' cells at this point;
// rotation: StrataKey::block's (the index of the indirect direction that found this point).
template <FeatureMask F>
TRAZO_HD Vec3 directLight(const SceneView& scene, const ShadingPoint& sp, const MaterialData& m,
                          const StrataKey& strata, uint32_t lightBlock, uint32_t rotation, SampleStream& rng,
                          uint32_t& rays) {
    Vec3 sum(0.0f);
    const PointBrdf brdf(sp, m);
    if (!brdf.reflects()) return sum;  // Shade is 0 for every light: no shadow rays
    for (uint32_t i = 0; i < scene.pointLights.count; ++i) {
        const PointLightData& light = scene.pointLights[i];
        sum += shadeFromPoint(scene, sp, brdf, light.position, light.color, rays);
    }
    if constexpr ((F & kFeatureAreaLights) != 0) {
    for (uint32_t i = 0; i < scene.areaLights.count; ++i) {
        const AreaLightData& light = scene.areaLights[i];
        const StrataBlock cells =
            strata.block(kGridAreaLightBase + i, light.cellsU * light.cellsV, lightBlock, rotation);
        Vec3 lightSum(0.0f);
#if TRAZO_SHADOW_PACKETS
        if (cells.size >= kMinShadowPacket) {
            lightSum = shadeCellsTogether(scene, sp, brdf, light, cells, rng, rays);
        } else
#endif
        for (uint32_t j = 0; j < cells.size; ++j)
            lightSum += shadeFromPoint(scene, sp, brdf, cellPoint(light, cells.stratum(j), rng), light.color, rays);
        sum += cells.size == 1 ? lightSum : lightSum / float(cells.size);
    }
    }
    return sum;
}

}  // namespace trazo
