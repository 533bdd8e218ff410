// Host only: Direct(P) with shadow rays traced in packets: an area light's cells from one point, and the point
// lights from many points (a block's, or the points indirect directions found), the same sums bit for bit.
#pragma once

#include "integrator/packets/occluded_packet.h"
#include "integrator/strata.h"
#include "integrator/thesis/shade_from_point.h"

namespace trazo {

// Host: blocks of fewer cells take shadeFromPoint ray by ray (a packet's set-up costs more than it saves).
constexpr uint32_t kMinShadowPacket = 4;

// Host: evalCookTorrance(n, l, v, roughness) in SIMD lanes, one l per lane, operation for operation (minOf(a, b)
// is a < b ? a : b, maxOf a > b ? a : b); n, v and the roughness one for all lanes (Vec3, float) or one per lane
// (V3, LaneF). expf only in the lanes of `lanes` (libm's, lane by lane, as the scalar code calls it).
template <class Vec, class Real>
inline packet_detail::LaneF cookTorranceLanes(const Vec& n, const Vec& v, const packet_detail::V3& l, Real roughness,
                                              uint64_t lanes) {
    using namespace packet_detail;
    const LaneF one = splat(1.0f);
    const LaneF m = maxOf(asLanes(roughness), splat(0.01f));
    const V3 sum = {l.x + v.x, l.y + v.y, l.z + v.z};
    const LaneF inv = 1.0f / sqrt(dot(sum, sum));
    const V3 h = {sum.x * inv, sum.y * inv, sum.z * inv};
    const LaneF nh0 = dot(n, h);
    const LaneF nh = nh0 < 1.0f ? nh0 : one;
    const LaneF nv = asLanes(dot(n, v));
    const LaneF nl = dot(n, l);
    const LaneF vh = dot(v, h);
    const LaneI none = (nh <= 0.0f) | (vh <= 0.0f);
    const LaneF nh2 = nh * nh;
    const LaneF tan2 = (1.0f - nh2) / nh2;
    const LaneF m2 = m * m;
    const LaneF exponent = -tan2 / m2;
    LaneF e = splat(0.0f);
    for (uint64_t left = lanes & ~bits(none); left; left &= left - 1) {
        const int i = __builtin_ctzll(left);
        e[i] = expf(exponent[i]);
    }
    const LaneF piD = e / (m2 * nh2 * nh2);
    const LaneF nearer = nv < nl ? nv : nl;
    const LaneF g2 = 2.0f * nh * nearer / vh;
    const LaneF gTerm = 1.0f < g2 ? one : g2;
    return none ? splat(0.0f) : piD * gTerm / (4.0f * nv);
}

// Host: brdf.eval(l) for the rays of `lanes` in group g of the packet, in SIMD lanes: PointBrdf::eval with
// evalOrenNayar and evalCookTorrance (cookTorranceLanes) operation for operation.
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
        const LaneF ct = cookTorranceLanes(n, brdf.sp.v, l, brdf.m.roughness, lanes);
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
// o, for the lanes of `lanes` (bit k: lane o + k): orenNayarView and evalOrenNayar operation for operation, then
// cookTorranceLanes, a black lobe adding nothing.
inline packet_detail::V3 evalPointBrdfLanes(const PointLanes& q, int o, const packet_detail::V3& l, uint64_t lanes) {
    using namespace packet_detail;
    const V3 n = PointLanes::lanes(q.nx, q.ny, q.nz, o), v = PointLanes::lanes(q.vx, q.vy, q.vz, o);
    const V3 kd = PointLanes::lanes(q.dr, q.dg, q.db, o), ks = PointLanes::lanes(q.sr, q.sg, q.sb, o);
    const LaneF sigma = load(q.roughness + o);
    const LaneF zero = splat(0.0f), one = splat(1.0f);
    // orenNayarView
    const LaneF s2 = sigma * sigma;
    const LaneF a = 1.0f - 0.5f * s2 / (s2 + 0.33f);
    const LaneF b = 0.45f * s2 / (s2 + 0.09f);
    const LaneF nv = dot(n, v);
    const LaneF cosV = nv < 1.0f ? nv : one;
    const LaneF sin2 = 1.0f - cosV * cosV;
    const LaneF sinV = sqrt(0.0f > sin2 ? zero : sin2);
    const V3 vt0 = {v.x - n.x * cosV, v.y - n.y * cosV, v.z - n.z * cosV};
    const LaneF vt2 = dot(vt0, vt0);
    const LaneF invVt = 1.0f / sqrt(vt2);
    const LaneI hasVt = vt2 > 0.0f;
    const V3 vt = {hasVt ? vt0.x * invVt : zero, hasVt ? vt0.y * invVt : zero, hasVt ? vt0.z * invVt : zero};
    // evalOrenNayar
    const LaneF nl = dot(n, l);
    const LaneF cosL = nl < 1.0f ? nl : one;
    const LaneF lvt = dot(l, vt);
    const LaneF azimuth = 0.0f > lvt ? zero : lvt;
    const LaneF slope = cosL <= cosV ? (cosL / cosV) * sinV : sinV;
    const LaneF on = b == 0.0f ? cosL * a : cosL * a + b * azimuth * slope;
    const LaneI diffuse = ~((kd.x == 0.0f) & (kd.y == 0.0f) & (kd.z == 0.0f));
    V3 f = {diffuse ? kd.x * on : zero, diffuse ? kd.y * on : zero, diffuse ? kd.z * on : zero};
    const LaneI specular = ~((ks.x == 0.0f) & (ks.y == 0.0f) & (ks.z == 0.0f));
    const uint64_t specularLanes = lanes & bits(specular);
    if (!specularLanes) return f;
    const LaneF ct = cookTorranceLanes(n, v, l, sigma, specularLanes);
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
