// Host only: the shading of a block of pixels whose camera rays were traced together (camera_packet.h), with the rays
// each pixel's shading sends traced together across the block: the shadow rays of all the block's points towards each
// point light, and the indirect directions of all its points, each ray from its own origin. For the render variants
// whose every ray is one of those (point lights, and at most indirect light); thesisSample given the same hits, bit
// for bit, is what each pixel gets.
#pragma once

#include <new>

#include "integrator/packets/nearest_packet.h"
#include "integrator/thesis/thesis_integrator.h"

namespace trazo {

// Whether thesisSample<F> of a pixel given its camera ray is one value in every pass: F has nothing that draws a
// random number or picks a stratum (no area lights, reflection, refraction, indirect light or rare features), so with
// one camera ray per pixel (cameraPacketsApply) only point lights' hard shadows remain.
template <FeatureMask F>
constexpr bool directOnlySample() {
    return (F & kAllSampleFeatures) == 0;
}

// Whether shadeBlock serves F: point lights and, at most, indirect light (whose directions draw random numbers per
// pass, but Direct(Q) of point lights none, so each pixel's draws stay in its own stream's order).
template <FeatureMask F>
constexpr bool blockShadingServes() {
    return (F & kAllSampleFeatures & ~kFeatureIndirect) == 0;
}

namespace block_detail {

// The camera ray's hit of each pixel of `active`, up to its shading: color[i] its emission (or the background, a
// light's colour), and where an object is hit its shading point, material and directWeight; `lit`: the pixels whose
// Direct(P) and Indirect(P) enter (directWeight > 0).
struct BlockPoints {
    PerRay<ShadingPoint> points;
    PerRay<MaterialData> materials;
    float directWeight[kPacketRays];
    uint64_t lit = 0;
};

inline void shadeCameraHits(const SceneView& scene, const TracedRay* hits, uint64_t active, BlockPoints& b,
                            Vec3* color) {
    const Vec3 weight(1.0f);  // the camera ray's
    for (uint64_t m = active; m; m &= m - 1) {
        const int i = __builtin_ctzll(m);
        const TracedRay& r = hits[i];
        Vec3 c(0.0f);
        if (!r.found) {
            c += weight * missRadiance<kAllSampleFeatures>(scene, r.ray.direction);
        } else if (r.hit.object == kNoObject) {
            c += weight * scene.areaLights[r.hit.areaLight].color;
        } else {
            new (b.points.data() + i) ShadingPoint(shadingPointAt(scene, r.ray, r.hit, b.materials[i]));
            c += weight * b.materials[i].emissive;
            b.directWeight[i] = (1.0f - 0.0f) * b.materials[i].opacity;  // (1 − a)·opacity, no reflection: a = 0
            if (b.directWeight[i] > 0.0f) b.lit |= 1ull << i;
        }
        color[i] = c;
    }
}

// directPointLightsTogether over `at`. GCC takes the const arrays for read whole, where only the elements of `at` are
// read (and written before).
inline void directOfPoints(const SceneView& scene, PerRay<ShadingPoint>& points, PerRay<MaterialData>& materials,
                           uint64_t at, PerRay<Vec3>& out, uint32_t& rays) {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
    directPointLightsTogether(scene, points.data(), materials.data(), at, out.data(), rays);
#pragma GCC diagnostic pop
}

// indirectLightOneByOne's sums for the block's points of `at`, into sum[i], their directions traced kPacketRays at a
// time whichever points they leave from. Directions of a point are drawn from its own stream in order (two draws
// each, nothing else draws), and each point's terms are added in its directions' order: the loop's sums.
inline void indirectOfPoints(const SceneView& scene, BlockPoints& b, uint64_t at, const StrataBlock* directions,
                             SampleStream* streams, Vec3* sum, uint32_t& rays) {
    const uint32_t q = scene.settings.indirectQuality;
    OrenNayarView views[kPacketRays];
    RayPacket packet;
    RayOrigins origins;
    uint8_t owner[kPacketRays];  // the point each ray of the packet leaves from
    alignas(64) float wx[kPacketRays], wy[kPacketRays], wz[kPacketRays];  // one point's directions
    PerRay<TracedRay> traced;
    PointLanes qPoints;  // the points Q the directions find, and their materials
    PerRay<Vec3> fromQ;
    int used = 0;
    auto flush = [&] {
        for (int k = used; k < kPacketRays; ++k) {  // never traced, but read whole by the packet's set-up
            origins.ox[k] = origins.oy[k] = origins.oz[k] = 0.0f;
            packet.dx[k] = packet.dy[k] = 0.0f;
            packet.dz[k] = 1.0f;
            packet.tMax[k] = INFINITY;
        }
        const uint64_t active = used == kPacketRays ? ~0ull : (1ull << used) - 1;
        tracePacket(scene, origins, packet, active, traced.data());
        const uint64_t atObject = lightFromFoundPoints(scene, traced, active, qPoints, fromQ, rays);
        for (uint64_t m = atObject; m; m &= m - 1) {
            const int k = __builtin_ctzll(m), i = owner[k];
            const float on = evalOrenNayar(views[i], b.points[i].n, traced[k].ray.direction);
            sum[i] += b.materials[i].diffuse * on * fromQ[k];
        }
        used = 0;
    };
    for (uint64_t m = at; m; m &= m - 1) {
        const int i = __builtin_ctzll(m);
        const ShadingPoint& sp = b.points[i];
        views[i] = orenNayarView(sp.n, sp.v, b.materials[i].roughness);
        sum[i] = Vec3(0.0f);
        const ConeFrame about = coneFrame(sp.n);
        for (uint32_t first = 0; first < directions[i].size; first += kPacketRays) {
            const uint32_t count = directions[i].size - first < kPacketRays ? directions[i].size - first : kPacketRays;
            // Those below the geometric surface contribute 0: not traced.
            const uint64_t above = indirectDirectionsLanes(about, directions[i], first, count, q, sp.ng, streams[i],
                                                           wx, wy, wz);
            for (uint64_t left = above; left; left &= left - 1) {
                const int k = __builtin_ctzll(left);
                ++rays;
                origins.ox[used] = sp.above.x, origins.oy[used] = sp.above.y, origins.oz[used] = sp.above.z;
                packet.dx[used] = wx[k], packet.dy[used] = wy[k], packet.dz[used] = wz[k];
                packet.tMax[used] = INFINITY;
                owner[used] = uint8_t(i);
                if (++used == kPacketRays) flush();
            }
        }
    }
    if (used > 0) flush();
}

}  // namespace block_detail

// Host: thesisSample<F>(scene, frame, imageX[i], imageY[i], pass, rays, &hits[i]) of each pixel of `active` into
// color[i], for F where blockShadingServes, bit for bit; returns the rays. The shadow rays of the block's points
// towards each point light are traced together, and so are their indirect directions (indirectOfPoints).
template <FeatureMask F>
inline uint32_t shadeBlock(const SceneView& scene, const FrameParams& frame, const TracedRay* hits,
                           const uint32_t* imageX, const uint32_t* imageY, uint64_t active, uint32_t pass,
                           Vec3* color) {
    static_assert(blockShadingServes<F>(), "a weight of 1, no reflected or transmitted rays, no area lights");
    using namespace block_detail;
    uint32_t rays = (uint32_t)__builtin_popcountll(active);  // the camera rays
    BlockPoints b;
    shadeCameraHits(scene, hits, active, b, color);
    PerRay<Vec3> local;  // Direct(P), then + Indirect(P)
    directOfPoints(scene, b.points, b.materials, b.lit, local, rays);
    if constexpr ((F & kFeatureIndirect) != 0) {
        const RenderSettings& settings = scene.settings;
        const uint32_t q = settings.indirectQuality;
        uint64_t gathers = 0;  // indirectLight's points that send directions
        PerRay<StrataBlock> directions;
        PerRay<SampleStream> streams;
        if (q != 0 && settings.colorBleeding > 0.0f) {
            for (uint64_t m = b.lit; m; m &= m - 1) {
                const int i = __builtin_ctzll(m);
                const ShadingPoint& sp = b.points[i];
                if (isBlack(b.materials[i].diffuse) || dot(sp.n, sp.v) <= 0.0f) continue;
                const uint32_t pixelIndex = imageY[i] * frame.camera.width + imageX[i];
                const StrataKey strata{frame.strataSeed(pass), pixelIndex, pass, kSampleTreeRoot};
                new (directions.data() + i) StrataBlock(strata.block(kGridIndirect, 2 * q * q, frame.blocks.indirect));
                new (streams.data() + i) SampleStream(frame.seed, pixelIndex, pass);
                gathers |= 1ull << i;
            }
        }
        PerRay<Vec3> sum;
        indirectOfPoints(scene, b, gathers, directions.data(), streams.data(), sum.data(), rays);
        for (uint64_t m = b.lit; m; m &= m - 1) {  // indirectLight's answer, 0 where it sends no directions
            const int i = __builtin_ctzll(m);
            local[i] += gathers >> i & 1u ? sum[i] * (settings.colorBleeding / float(directions[i].size)) : Vec3(0.0f);
        }
    }
    for (uint64_t m = b.lit; m; m &= m - 1) {
        const int i = __builtin_ctzll(m);
        color[i] += Vec3(1.0f) * (local[i] * b.directWeight[i]);
    }
    for (uint64_t m = active; m; m &= m - 1) {  // thesisSample's sum of its one position
        const int i = __builtin_ctzll(m);
        Vec3 sample(0.0f);
        sample += color[i];
        color[i] = sample;
    }
    return rays;
}

}  // namespace trazo
