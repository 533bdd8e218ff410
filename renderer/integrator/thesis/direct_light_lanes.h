// Host only: Direct(P) with shadow rays traced in packets: an area light's cells from one point, and the point
// lights from many points (a block's, or the points indirect directions found), the same sums bit for bit.
#pragma once

#include "integrator/packets/occluded_packet.h"
#include "integrator/strata.h"
#include "integrator/thesis/shade_from_point.h"

namespace trazo {

// Host: blocks of fewer cells take shadeFromPoint ray by ray (a packet's set-up costs more than it saves).
constexpr uint32_t kMinShadowPacket = 4;

// Host: brdf.eval(l) for the rays of `lanes` in group g of the packet, in SIMD lanes (evalOrenNayarOf and
// cookTorranceOf for LaneOps, the point's n, v and view one for all lanes).
inline void evalBrdfLanes(const PointBrdf& brdf, const RayPacket& packet, int g, uint64_t lanes, float* fx,
                          float* fy, float* fz) {
    using namespace packet_detail;
    const int o = g * kLanes;
    const V3 l = {load(packet.dx + o), load(packet.dy + o), load(packet.dz + o)};
    const Vec3 n = brdf.sp.n;
    V3 f = {splat(0.0f), splat(0.0f), splat(0.0f)};
    if (brdf.hasDiffuse) {
        const LaneF on = evalOrenNayarOf<LaneOps>(brdf.diffuseView, n, l);
        const Vec3 d = brdf.m.diffuse;
        f = {d.x * on, d.y * on, d.z * on};
    }
    if (brdf.hasSpecular) {
        const LaneF ct = cookTorranceOf<LaneOps>(n, l, brdf.sp.v, brdf.m.roughness, laneMask(lanes));
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
    alignas(64) float fx[kPacketRays], fy[kPacketRays], fz[kPacketRays];  // brdf.eval of the visible cells
    for (uint32_t start = 0; start < cells.size; start += kPacketRays) {
        const uint32_t count = cells.size - start < kPacketRays ? cells.size - start : kPacketRays;
        cells.gridCells(start, count, light.cellsU, kPacketRays, column, row);
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

// Host: up to kPacketRays shading points and their materials, structure of arrays, so that each SIMD lane can
// shade its own point (directLightOfLanes).
struct PointLanes {
    alignas(64) float px[kPacketRays], py[kPacketRays], pz[kPacketRays];  // p
    alignas(64) float gx[kPacketRays], gy[kPacketRays], gz[kPacketRays];  // ng
    alignas(64) float nx[kPacketRays], ny[kPacketRays], nz[kPacketRays];  // n
    alignas(64) float vx[kPacketRays], vy[kPacketRays], vz[kPacketRays];  // v
    alignas(64) float ax[kPacketRays], ay[kPacketRays], az[kPacketRays];  // above
    alignas(64) float offset[kPacketRays];
    alignas(64) float dr[kPacketRays], dg[kPacketRays], db[kPacketRays];  // the material's diffuse colour
    alignas(64) float sr[kPacketRays], sg[kPacketRays], sb[kPacketRays];  // its specular colour
    alignas(64) float roughness[kPacketRays];

    void setPoint(int i, const ShadingPoint& sp) {
        px[i] = sp.p.x, py[i] = sp.p.y, pz[i] = sp.p.z;
        gx[i] = sp.ng.x, gy[i] = sp.ng.y, gz[i] = sp.ng.z;
        nx[i] = sp.n.x, ny[i] = sp.n.y, nz[i] = sp.n.z;
        vx[i] = sp.v.x, vy[i] = sp.v.y, vz[i] = sp.v.z;
        ax[i] = sp.above.x, ay[i] = sp.above.y, az[i] = sp.above.z;
        offset[i] = sp.offset;
    }
    void setMaterial(int i, const MaterialData& m) {
        dr[i] = m.diffuse.x, dg[i] = m.diffuse.y, db[i] = m.diffuse.z;
        sr[i] = m.specular.x, sg[i] = m.specular.y, sb[i] = m.specular.z;
        roughness[i] = m.roughness;
    }
    // Zeros in lane i: never shaded, but computed in its group.
    void clear(int i) {
        px[i] = py[i] = pz[i] = gx[i] = gy[i] = gz[i] = nx[i] = ny[i] = nz[i] = 0.0f;
        vx[i] = vy[i] = vz[i] = ax[i] = ay[i] = az[i] = offset[i] = 0.0f;
        dr[i] = dg[i] = db[i] = sr[i] = sg[i] = sb[i] = roughness[i] = 0.0f;
    }
    // The lanes of `at` whose point reflects light (reflectsLight).
    uint64_t reflecting(uint64_t at) const {
        uint64_t r = 0;
        for (uint64_t left = at; left; left &= left - 1) {
            const int i = __builtin_ctzll(left);
            if (reflectsLight(Vec3(dr[i], dg[i], db[i]), Vec3(sr[i], sg[i], sb[i]), Vec3(nx[i], ny[i], nz[i]),
                              Vec3(vx[i], vy[i], vz[i])))
                r |= 1ull << i;
        }
        return r;
    }
    // ShadingPoint::rayOrigin of lane i towards the side below its geometric normal.
    Vec3 originBelow(int i) const {
        return bumpedOrigin(Vec3(px[i], py[i], pz[i]), -(Vec3(gx[i], gy[i], gz[i]) * offset[i]));
    }
    static packet_detail::V3 lanes(const float* x, const float* y, const float* z, int o) {
        return {packet_detail::load(x + o), packet_detail::load(y + o), packet_detail::load(z + o)};
    }
};

// Host: PointBrdf(sp, m).eval(l) of the point and material in lane i of q, in lane i of the group at lane offset
// o, for the lanes of `lanes` (bit k: lane o + k): orenNayarViewOf, evalOrenNayarOf and cookTorranceOf for
// LaneOps, a black lobe adding nothing.
inline packet_detail::V3 evalPointBrdfLanes(const PointLanes& q, int o, const packet_detail::V3& l, uint64_t lanes) {
    using namespace packet_detail;
    const V3 n = PointLanes::lanes(q.nx, q.ny, q.nz, o), v = PointLanes::lanes(q.vx, q.vy, q.vz, o);
    const V3 kd = PointLanes::lanes(q.dr, q.dg, q.db, o), ks = PointLanes::lanes(q.sr, q.sg, q.sb, o);
    const LaneF sigma = load(q.roughness + o);
    const LaneF zero = splat(0.0f);
    const LaneF on = evalOrenNayarOf<LaneOps>(orenNayarViewOf<LaneOps>(n, v, sigma), n, l);
    const LaneI diffuse = !((kd.x == 0.0f) & (kd.y == 0.0f) & (kd.z == 0.0f));
    V3 f = {diffuse ? kd.x * on : zero, diffuse ? kd.y * on : zero, diffuse ? kd.z * on : zero};
    const LaneI specular = laneMask(lanes) & !((ks.x == 0.0f) & (ks.y == 0.0f) & (ks.z == 0.0f));
    if (!LaneOps::any(specular)) return f;
    const LaneF ct = cookTorranceOf<LaneOps>(n, l, v, sigma, specular);
    return {specular ? f.x + ks.x * ct : f.x, specular ? f.y + ks.y * ct : f.y, specular ? f.z + ks.z * ct : f.z};
}

// Host: directLight<F> for F without area lights (point lights only) at the points of q's lanes `reflecting` (those
// that reflect light, PointLanes::reflecting) added to out[i] (0 where a point sees no light): for each light in
// turn, the points' shadow rays aimed in SIMD lanes (as aimShadowRay), traced together, each from its own origin
// (occludedPacket), and the BRDF of the visible ones in lanes (evalPointBrdfLanes). The same rays and sums as
// directLight, bit for bit.
inline void directLightOfLanes(const SceneView& scene, const PointLanes& q, uint64_t reflecting, Vec3* out,
                               uint32_t& rays) {
    using namespace packet_detail;
    if (!reflecting) return;
    const int lanesUsed = groupedLanes(reflecting);
    RayPacket packet;
    RayOrigins origins;
    for (int i = lanesUsed; i < kPacketRays; ++i) {  // never traced, but read whole by the packet's set-up
        origins.ox[i] = origins.oy[i] = origins.oz[i] = 0.0f;
        packet.dx[i] = packet.dy[i] = packet.tMax[i] = 0.0f;
        packet.dz[i] = 1.0f;
    }
    alignas(64) float fx[kPacketRays], fy[kPacketRays], fz[kPacketRays];
    const LaneF zero = splat(0.0f);
    for (uint32_t k = 0; k < scene.pointLights.count; ++k) {
        const PointLightData& light = scene.pointLights[k];
        const Vec3 x = light.position;
        uint64_t aimed = 0;
        for (int o = 0; o < lanesUsed; o += kLanes) {  // aimShadowRay: l, and the origin above the surface
            const V3 p = PointLanes::lanes(q.px, q.py, q.pz, o), n = PointLanes::lanes(q.nx, q.ny, q.nz, o);
            const V3 toLight = {x.x - p.x, x.y - p.y, x.z - p.z};
            const LaneF dist = sqrt(dot(toLight, toLight));
            const LaneF inv = 1.0f / dist;
            const V3 l = {toLight.x * inv, toLight.y * inv, toLight.z * inv};
            const uint64_t lanes = (reflecting >> o & kGroupBits) & bits((dist > 0.0f) & ~(dot(n, l) <= 0.0f));
            LaneI laneAimed;
            for (int i = 0; i < kLanes; ++i) laneAimed[i] = lanes >> i & 1u ? -1 : 0;
            const LaneF dx = laneAimed ? l.x : zero, dy = laneAimed ? l.y : zero, dz = laneAimed ? l.z : splat(1.0f);
            const LaneF ox = laneAimed ? load(q.ax + o) : zero, oy = laneAimed ? load(q.ay + o) : zero,
                        oz = laneAimed ? load(q.az + o) : zero;
            std::memcpy(packet.dx + o, &dx, sizeof dx);
            std::memcpy(packet.dy + o, &dy, sizeof dy);
            std::memcpy(packet.dz + o, &dz, sizeof dz);
            std::memcpy(origins.ox + o, &ox, sizeof ox);
            std::memcpy(origins.oy + o, &oy, sizeof oy);
            std::memcpy(origins.oz + o, &oz, sizeof oz);
            const V3 ng = PointLanes::lanes(q.gx, q.gy, q.gz, o);
            for (uint64_t down = lanes & bits(dot(l, ng) < 0.0f); down; down &= down - 1) {  // rayOrigin below
                const int i = o + __builtin_ctzll(down);
                const Vec3 origin = q.originBelow(i);
                origins.ox[i] = origin.x, origins.oy[i] = origin.y, origins.oz[i] = origin.z;
            }
            const V3 toEnd = {x.x - load(origins.ox + o), x.y - load(origins.oy + o), x.z - load(origins.oz + o)};
            const LaneF tMax = laneAimed ? sqrt(dot(toEnd, toEnd)) : zero;
            std::memcpy(packet.tMax + o, &tMax, sizeof tMax);
            aimed |= lanes << o;
        }
        rays += (uint32_t)__builtin_popcountll(aimed);
        const uint64_t visible = aimed & ~occludedPacket(scene, origins, packet, aimed);
        for (int o = 0; o < lanesUsed; o += kLanes) {
            const uint64_t lanes = visible >> o & kGroupBits;
            if (!lanes) continue;
            const V3 f = evalPointBrdfLanes(q, o, PointLanes::lanes(packet.dx, packet.dy, packet.dz, o), lanes);
            std::memcpy(fx + o, &f.x, sizeof f.x);
            std::memcpy(fy + o, &f.y, sizeof f.y);
            std::memcpy(fz + o, &f.z, sizeof f.z);
        }
        for (uint64_t left = reflecting; left; left &= left - 1) {
            const int i = __builtin_ctzll(left);
            out[i] += visible >> i & 1u ? light.color * Vec3(fx[i], fy[i], fz[i]) : Vec3(0.0f);
        }
    }
}

// Host: directLight<F> for F without area lights at each point of `at` (bit i: points[i] with materials[i]) into
// out[i] (directLightOfLanes).
inline void directPointLightsTogether(const SceneView& scene, const ShadingPoint* points,
                                      const MaterialData* materials, uint64_t at, Vec3* out, uint32_t& rays) {
    PointLanes q;
    const int used = packet_detail::groupedLanes(at);
    for (int i = 0; i < used; ++i) {
        if (at >> i & 1u) {
            q.setPoint(i, points[i]);
            q.setMaterial(i, materials[i]);
            out[i] = Vec3(0.0f);
        } else {
            q.clear(i);
        }
    }
    directLightOfLanes(scene, q, q.reflecting(at), out, rays);
}

}  // namespace trazo
