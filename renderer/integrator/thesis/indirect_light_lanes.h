// Host only: Indirect(P) with a point's directions traced in packets and the shadow rays of the points Q they find
// traced together, the same sum bit for bit (indirectLightTogether).
#pragma once

#include <new>

#include "integrator/packets/nearest_packet.h"
#include "integrator/surface.h"
#include "integrator/thesis/direct_light.h"

namespace trazo {

constexpr uint32_t kMinIndirectPacket = 4;  // fewer directions a pass are traced one by one (as kMinShadowPacket)

// Whether indirectLightTogether serves the scene: objects the packet lanes test (no meshes or CSG solids, whose
// rays would all be traced again) and, F without area lights, a direct light of point lights only, which draws
// no random numbers (so every direction's two draws can come before any Q is shaded and still be the loop's)
// and whose shadow rays from the Qs can be traced together (directPointLightsTogether).
template <FeatureMask F>
inline bool indirectPacketsApply(const SceneView& scene, uint32_t directions) {
    if constexpr ((F & kFeatureAreaLights) != 0) return false;
    return directions >= kMinIndirectPacket && scene.meshes.count == 0 && scene.csgs.count == 0;
}

// bumpedOrigin(p, offset) lane by lane (core/ray.h): p + offset, then one float further the way offset points
// (nextFloatUp, nextFloatDown) in integer lanes.
inline packet_detail::V3 bumpedOriginLanes(const packet_detail::V3& p, const packet_detail::V3& offset) {
    using namespace packet_detail;
    const auto up = [](LaneF v) {  // unsigned bits, as nextFloatUp's: −0's step below wraps, never overflows
        const LaneU b = (LaneU)v;
        const LaneU stepped = v > 0.0f ? b + 1u : b - 1u;
        const LaneU r = v == 0.0f ? LaneU{} + 1u : stepped;  // ±0: the smallest subnormal, bits 1
        return (LaneF)(v < INFINITY ? r : b);                // +∞ and NaN stay
    };
    const auto bump = [&](LaneF po, LaneF off) {
        const LaneF down = -up(-po);
        return off > 0.0f ? up(po) : (off < 0.0f ? down : po);
    };
    return {bump(p.x + offset.x, offset.x), bump(p.y + offset.y, offset.y), bump(p.z + offset.z, offset.z)};
}

// Host: the shading points at the hits of `lanes` (bit k: traced[k], on an object whose surface is the hit's
// normal: no textures, not a mesh) into q's points, in SIMD lanes, as shadingPointAlong makes them there operation
// for operation: p = pointAt, both normals the hit's turned to face the ray (facingShadingPoint), the offset of
// hitPointError's bound along ng and the origin above (ShadingPoint's constructor). Groups of lanes are written
// whole: lanes outside `lanes` are to be set after.
inline void facingPointsLanes(PerRay<TracedRay>& traced, uint64_t lanes, PointLanes& q) {
    using namespace packet_detail;
    if (!lanes) return;
    const int used = groupedLanes(lanes);
    alignas(64) float ox[kPacketRays], oy[kPacketRays], oz[kPacketRays];  // the rays' origins,
    alignas(64) float dx[kPacketRays], dy[kPacketRays], dz[kPacketRays];  // directions,
    alignas(64) float ex[kPacketRays], ey[kPacketRays], ez[kPacketRays];  // hitPointError
    alignas(64) float hx[kPacketRays], hy[kPacketRays], hz[kPacketRays];  // and the hits' normals
    alignas(64) float t[kPacketRays];
    for (int i = 0; i < used; ++i) {
        if (!(lanes >> i & 1u)) {
            ox[i] = oy[i] = oz[i] = dx[i] = dy[i] = dz[i] = ex[i] = ey[i] = ez[i] = hx[i] = hy[i] = hz[i] = t[i] = 0.0f;
            continue;
        }
        const TracedRay& r = traced[i];
        const Vec3 e = hitPointError(r.ray, r.hit.t);
        ox[i] = r.ray.origin.x, oy[i] = r.ray.origin.y, oz[i] = r.ray.origin.z;
        dx[i] = r.ray.direction.x, dy[i] = r.ray.direction.y, dz[i] = r.ray.direction.z;
        ex[i] = e.x, ey[i] = e.y, ez[i] = e.z;
        hx[i] = r.hit.normal.x, hy[i] = r.hit.normal.y, hz[i] = r.hit.normal.z;
        t[i] = r.hit.t;
    }
    const auto store = [](float* to, LaneF v) { std::memcpy(to, &v, sizeof v); };
    for (int o = 0; o < used; o += kLanes) {
        const V3 d = PointLanes::lanes(dx, dy, dz, o), h = PointLanes::lanes(hx, hy, hz, o);
        const V3 e = PointLanes::lanes(ex, ey, ez, o);
        const LaneF th = load(t + o);
        const V3 p = {load(ox + o) + d.x * th, load(oy + o) + d.y * th, load(oz + o) + d.z * th};
        const LaneI front = dot(d, h) < 0.0f;
        const V3 ng = {front ? h.x : -h.x, front ? h.y : -h.y, front ? h.z : -h.z};
        const LaneF offset = dot(abs(ng), e);
        const V3 above = bumpedOriginLanes(p, {ng.x * offset, ng.y * offset, ng.z * offset});
        store(q.px + o, p.x), store(q.py + o, p.y), store(q.pz + o, p.z);
        store(q.gx + o, ng.x), store(q.gy + o, ng.y), store(q.gz + o, ng.z);
        store(q.nx + o, ng.x), store(q.ny + o, ng.y), store(q.nz + o, ng.z);
        store(q.vx + o, -d.x), store(q.vy + o, -d.y), store(q.vz + o, -d.z);
        store(q.ax + o, above.x), store(q.ay + o, above.y), store(q.az + o, above.z);
        store(q.offset + o, offset);
    }
}

// What the traced directions of `traced` (bit k of `active`: ray k) found, where they found an object (not the
// sky, nor a light): Q's shading point and material in q's lane k (facingPointsLanes where it serves, else
// shadingPointAlong), and fromQ[k] = Direct(Q) + Ke(Q) with point lights only, the Qs' shadow rays traced together
// (directLightOfLanes). Returns those rays. lightArrivingFrom's values.
inline uint64_t lightFromFoundPoints(const SceneView& scene, PerRay<TracedRay>& traced, uint64_t active,
                                     PointLanes& q, PerRay<Vec3>& fromQ, uint32_t& rays) {
    uint64_t atObject = 0, plain = 0;
    const MaterialData* material[kPacketRays];
    for (uint64_t left = active; left; left &= left - 1) {
        const int k = __builtin_ctzll(left);
        const TracedRay& r = traced[k];
        if (!r.found || r.hit.object == kNoObject) continue;
        atObject |= 1ull << k;
        const ObjectRef& o = scene.objects[r.hit.object];
        material[k] = &scene.materials[o.material];
        if (o.kind != ObjectKind::Mesh && !materialHasTextures(*material[k])) plain |= 1ull << k;
    }
    if (!atObject) return 0;
    facingPointsLanes(traced, plain, q);
    PerRay<Vec3> emissive;
    const int used = packet_detail::groupedLanes(atObject);
    for (int k = 0; k < used; ++k) {
        if (plain >> k & 1u) {
            q.setMaterial(k, *material[k]);
            emissive[k] = material[k]->emissive;
        } else if (atObject >> k & 1u) {
            MaterialData m;
            q.setPoint(k, shadingPointAlong(scene, traced[k].ray, traced[k].hit, m));
            q.setMaterial(k, m);
            emissive[k] = m.emissive;
        } else {
            q.clear(k);
            continue;
        }
        fromQ[k] = Vec3(0.0f);
    }
    directLightOfLanes(scene, q, q.reflecting(atObject), fromQ.data(), rays);  // Direct(Q)
    for (uint64_t left = atObject; left; left &= left - 1) {
        const int k = __builtin_ctzll(left);
        fromQ[k] = fromQ[k] + emissive[k];  // Direct(Q) + Ke(Q)
    }
    return atObject;
}

// Host: the directions j = first … first + count − 1 (count ≤ kPacketRays) of a point's block into wx, wy, wz
// [0, count), as indirectDirection draws them one after another from rng (θ then φ, two draws each; rng moves on
// by 2·count): the strata, draws, sines and cosines (sinCosOf) and the cone's arithmetic in SIMD lanes, the
// same bits. Returns the directions indirectLightOneByOne traces, those not below the geometric surface ng (bit
// k: direction first + k).
inline uint64_t indirectDirectionsLanes(const ConeFrame& about, const StrataBlock& block, uint32_t first,
                                        uint32_t count, uint32_t q, Vec3 ng, SampleStream& rng, float* wx,
                                        float* wy, float* wz) {
    using namespace packet_detail;
    const int used = int(count + kLanes - 1) / kLanes * kLanes;
    alignas(64) float column[kPacketRays], row[kPacketRays];  // of each stratum in the q × 2q grid
    block.gridCells(first, count, q, uint32_t(used), column, row);
    LaneU lane;
    for (int i = 0; i < kLanes; ++i) lane[i] = uint32_t(i);
    const Vec3 a = about.axis, t1 = about.t1, t2 = about.t2;
    uint64_t traced = 0;
    for (int o = 0; o < used; o += kLanes) {
        const LaneU draw = rng.dimension + 2u * (uint32_t(o) + lane);
        const LaneF theta = (load(column + o) + unitFloats(rng.key, draw)) / float(q) * 1.57079632679f;
        const LaneF phi = (load(row + o) + unitFloats(rng.key, draw + 1u)) / float(2 * q) * 6.28318530718f;
        LaneF st, ct, sp, cp;  // directionInCone
        sinCosOf<LaneOps>(theta, st, ct);
        sinCosOf<LaneOps>(phi, sp, cp);
        const V3 v = {a.x * ct + (t1.x * cp + t2.x * sp) * st, a.y * ct + (t1.y * cp + t2.y * sp) * st,
                      a.z * ct + (t1.z * cp + t2.z * sp) * st};
        const LaneF inv = 1.0f / sqrt(dot(v, v));
        const V3 w = {v.x * inv, v.y * inv, v.z * inv};
        std::memcpy(wx + o, &w.x, sizeof w.x);
        std::memcpy(wy + o, &w.y, sizeof w.y);
        std::memcpy(wz + o, &w.z, sizeof w.z);
        traced |= bits(~(dot(ng, w) <= 0.0f)) << o;
    }
    rng.dimension += 2u * count;
    return traced & (count == (uint32_t)kPacketRays ? ~0ull : (1ull << count) - 1);
}

// Host: indirectLightOneByOne with the directions traced kPacketRays at a time as one packet (tracePacket: every
// direction above the geometric surface leaves from sp.above), and the shadow rays of the points Q they find
// towards each point light as another (lightFromFoundPoints). The same draws, rays and sum, bit for bit,
// where indirectPacketsApply.
template <FeatureMask F>
inline Vec3 indirectLightTogether(const SceneView& scene, const ShadingPoint& sp, const MaterialData& m,
                                  const StrataBlock& directions, SampleStream& rng, uint32_t& rays) {
    static_assert((F & kFeatureAreaLights) == 0, "Direct(Q) of point lights only: directPointLightsTogether");
    const OrenNayarView view = orenNayarView(sp.n, sp.v, m.roughness);
    RayPacket packet;
    PerRay<TracedRay> traced;
    PointLanes points;  // Q and its material, where atObject
    PerRay<Vec3> fromQ;
    const ConeFrame about = coneFrame(sp.n);
    Vec3 sum(0.0f);
    for (uint32_t start = 0; start < directions.size; start += kPacketRays) {
        const uint32_t count = directions.size - start < kPacketRays ? directions.size - start : kPacketRays;
        const uint64_t active = indirectDirectionsLanes(about, directions, start, count, scene.settings.indirectQuality,
                                                        sp.ng, rng, packet.dx, packet.dy, packet.dz);
        for (uint32_t i = 0; i < (uint32_t)kPacketRays; ++i) {
            if (i >= count) packet.dx[i] = packet.dy[i] = 0.0f, packet.dz[i] = 1.0f;  // never traced
            packet.tMax[i] = INFINITY;
        }
        rays += (uint32_t)__builtin_popcountll(active);
        tracePacket(scene, sp.above, packet, active, traced.data());
        const uint64_t atObject = lightFromFoundPoints(scene, traced, active, points, fromQ, rays);
        for (uint64_t left = atObject; left; left &= left - 1) {
            const int i = __builtin_ctzll(left);
            sum += m.diffuse * evalOrenNayar(view, sp.n, traced[i].ray.direction) * fromQ[i];
        }
    }
    return sum;
}
}  // namespace trazo
