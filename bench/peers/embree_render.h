// embree_render's shared parts: the Embree scene and its shading tables, the render job, the camera and the
// Lambertian light sum. Both modes (embree_single.cpp, embree_stream.cpp) shade through these same inline
// functions, so for one seed they compute the same floats in the same order and write the same image.
#pragma once

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace embree_peer {

using trazo::Vec3;

constexpr unsigned kMaskOccluder = 1, kMaskLight = 2;
constexpr float kShadowTfar = 1.0f - 1e-4f;  // shadow rays run from P to X - P unnormalised: t = 1 is the light point

struct AreaLightGrid {
    Vec3 center, u, v;  // u, v: full edge vectors (Width·û, Height·v̂)
    Vec3 color;
    int cellsU, cellsV;
};

// What the shading needs, indexed by Embree's geomID and primID.
struct ShadingTables {
    std::vector<Vec3> boxKd;       // per box (primID / 12)
    std::vector<Vec3> sphereKd;    // per sphere (primID)
    std::vector<Vec3> lightColor;  // per area light (primID / 2)
    unsigned boxGeom = RTC_INVALID_GEOMETRY_ID, sphereGeom = RTC_INVALID_GEOMETRY_ID,
             lightGeom = RTC_INVALID_GEOMETRY_ID;
};

// Boxes as triangles, spheres as SPHERE_POINT, light rectangles under kMaskLight; commits the scene.
void buildEmbreeScene(const trazo::Scene& scene, RTCDevice device, RTCScene rtc, ShadingTables& tables,
                      std::vector<AreaLightGrid>& grids);

enum class ShadowStream { Np, OneM };  // rtcOccludedNp (SoA) or rtcOccluded1M (an array of RTCRay)

// Everything a tile worker reads; the counters are the only shared writes.
struct RenderJob {
    const trazo::Scene* scene;
    RTCScene rtc;
    const ShadingTables* tables;
    const std::vector<AreaLightGrid>* grids;
    int width, height, samplesPerCell;
    uint64_t seed;
    Vec3 origin, forward, right, up;
    float tanHalfFovY;
    // The stream mode's choices.
    int packet = 16;  // camera rays per rtcIntersect4/8/16 call; 1: rtcIntersect1 each
    ShadowStream shadowStream = ShadowStream::OneM;
    bool coherentCamera = true, coherentShadows = true;
    std::vector<Vec3>* image;
    std::atomic<int> nextTile{0};
    std::atomic<uint64_t> rays{0};
};

void renderTilesSingle(RenderJob& job);  // rtcIntersect1 / rtcOccluded1 per ray (embree_single.cpp)
void renderTilesStream(RenderJob& job);  // packets and one shadow stream per tile (embree_stream.cpp)

// SplitMix64: a per-pixel stream, so the image depends on the seed only, not on threads, tiles or mode.
struct PixelRng {
    uint64_t state;
    float next() {
        uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return float((z ^ (z >> 31)) >> 40) * (1.0f / 16777216.0f);
    }
};

// The camera ray through the centre of pixel (px, py) (SPEC §3: vertical FOV).
inline Vec3 cameraDirection(const RenderJob& job, int px, int py) {
    const float sx = (2.0f * (px + 0.5f) / job.width - 1.0f) * job.tanHalfFovY * job.width / job.height;
    const float sy = (1.0f - 2.0f * (py + 0.5f) / job.height) * job.tanHalfFovY;
    return trazo::normalize(job.forward + job.right * sx + job.up * sy);
}

// What a camera ray found: the pixel's colour outright (background, a light's rectangle), or a lit surface.
struct Surface {
    bool lit = false;
    Vec3 color;     // when !lit
    Vec3 p, n, kd;  // when lit: the shadow rays' origin, the normal facing the viewer, Kd
};

inline Surface surfaceAt(const RenderJob& job, Vec3 dir, unsigned geomID, unsigned primID, float tfar, Vec3 ng) {
    const ShadingTables& t = *job.tables;
    Surface s;
    if (geomID == RTC_INVALID_GEOMETRY_ID) return s.color = job.scene->settings.backgroundColor, s;
    if (geomID == t.lightGeom) return s.color = t.lightColor[primID / 2], s;
    s.lit = true;
    s.kd = geomID == t.boxGeom ? t.boxKd[primID / 12] : t.sphereKd[primID];
    s.n = trazo::normalize(ng);
    if (trazo::dot(s.n, dir) > 0.0f) s.n = -s.n;  // face the viewer (SPEC §5)
    // Shadow rays start off the surface by an offset that scales with the hit point's magnitude.
    const Vec3 hit = job.origin + dir * tfar;
    const float scale = std::max({1.0f, std::fabs(hit.x), std::fabs(hit.y), std::fabs(hit.z)});
    s.p = hit + s.n * (1e-4f * scale);
    return s;
}

// The camera ray through pixel (px, py) traced alone (rtcIntersect1): what it found.
inline Surface cameraHit1(const RenderJob& job, RTCIntersectContext* ctx, int px, int py) {
    const Vec3 dir = cameraDirection(job, px, py);
    RTCRayHit rh{};
    rh.ray.org_x = job.origin.x, rh.ray.org_y = job.origin.y, rh.ray.org_z = job.origin.z;
    rh.ray.dir_x = dir.x, rh.ray.dir_y = dir.y, rh.ray.dir_z = dir.z;
    rh.ray.tfar = INFINITY;
    rh.ray.mask = kMaskOccluder | kMaskLight;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(job.rtc, ctx, &rh);
    return surfaceAt(job, dir, rh.hit.geomID, rh.hit.primID, rh.ray.tfar, Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
}

// Whether light from X - P (toLight) reaches the side of N the viewer sees; if not, no shadow ray is traced.
inline bool facesLight(const Surface& s, Vec3 toLight) { return !(trazo::dot(s.n, toLight) <= 0.0f); }

// Kd·(N·L)·C of a light point at P + toLight, if nothing is in between.
inline Vec3 unshadowedTerm(const Surface& s, Vec3 toLight, Vec3 color) {
    return s.kd * color * (trazo::dot(s.n, toLight) / trazo::length(toLight));
}

// The pixel's light sum: each point light, then each area light's cells (K jittered points per cell) averaged.
// term(X, C) gives one light point's contribution; the stream mode records rays through it instead.
template <class Term>
Vec3 sumLights(const RenderJob& job, int px, int py, Term&& term) {
    Vec3 sum(0.0f);
    for (const trazo::PointLight& l : job.scene->pointLights) sum += term(l.position, l.color);
    PixelRng rng{job.seed * 0x100000001b3ull + (uint64_t)py * job.width + px};
    for (const AreaLightGrid& g : *job.grids) {
        Vec3 lightSum(0.0f);
        for (int j = 0; j < g.cellsV; ++j)
            for (int i = 0; i < g.cellsU; ++i)
                for (int k = 0; k < job.samplesPerCell; ++k) {
                    const float su = (i + rng.next()) / g.cellsU - 0.5f, sv = (j + rng.next()) / g.cellsV - 0.5f;
                    lightSum += term(g.center + g.u * su + g.v * sv, g.color);
                }
        sum += lightSum / float(g.cellsU * g.cellsV * job.samplesPerCell);
    }
    return sum;
}

// How many terms sumLights adds for one pixel.
inline int termsPerPixel(const RenderJob& job) {
    int n = (int)job.scene->pointLights.size();
    for (const AreaLightGrid& g : *job.grids) n += g.cellsU * g.cellsV * job.samplesPerCell;
    return n;
}

// sumLights's sum again, in its order and grouping, from term(C), which gives the next term of a light of
// colour C (the stream mode's second pass, once the shadow rays are traced).
template <class Term>
Vec3 sumTerms(const RenderJob& job, Term&& term) {
    Vec3 sum(0.0f);
    for (const trazo::PointLight& l : job.scene->pointLights) sum += term(l.color);
    for (const AreaLightGrid& g : *job.grids) {
        const int n = g.cellsU * g.cellsV * job.samplesPerCell;
        Vec3 lightSum(0.0f);
        for (int k = 0; k < n; ++k) lightSum += term(g.color);
        sum += lightSum / float(n);
    }
    return sum;
}

}  // namespace embree_peer
