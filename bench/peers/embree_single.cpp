// embree_render --mode single: one rtcIntersect1 per camera ray and one rtcOccluded1 per shadow ray, pixel by
// pixel over 16×16 tiles: the form a first Embree renderer takes (and the peer measured since 2026-12-01).
#include <algorithm>

#include "embree_render.h"

namespace embree_peer {
namespace {

constexpr int kTile = 16;

bool occludedSegment(RTCScene rtc, Vec3 from, Vec3 to) {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRay r{};
    r.org_x = from.x, r.org_y = from.y, r.org_z = from.z;
    const Vec3 d = to - from;
    r.dir_x = d.x, r.dir_y = d.y, r.dir_z = d.z;
    r.tnear = 0.0f;
    r.tfar = kShadowTfar;
    r.mask = kMaskOccluder;
    rtcOccluded1(rtc, &ctx, &r);
    return r.tfar < 0.0f;
}

Vec3 shadePixel(const RenderJob& job, int px, int py, uint64_t& rays) {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    const Surface s = cameraHit1(job, &ctx, px, py);
    ++rays;
    if (!s.lit) return s.color;
    return sumLights(job, px, py, [&](Vec3 x, Vec3 color) {
        const Vec3 toLight = x - s.p;
        if (!facesLight(s, toLight)) return Vec3(0.0f);
        ++rays;
        return occludedSegment(job.rtc, s.p, x) ? Vec3(0.0f) : unshadowedTerm(s, toLight, color);
    });
}

}  // namespace

void renderTilesSingle(RenderJob& job) {
    const int tilesX = (job.width + kTile - 1) / kTile, tilesY = (job.height + kTile - 1) / kTile;
    uint64_t rays = 0;
    for (int tile; (tile = job.nextTile++) < tilesX * tilesY;) {
        const int x0 = (tile % tilesX) * kTile, y0 = (tile / tilesX) * kTile;
        for (int y = y0; y < std::min(y0 + kTile, job.height); ++y)
            for (int x = x0; x < std::min(x0 + kTile, job.width); ++x)
                (*job.image)[(size_t)y * job.width + x] = shadePixel(job, x, y, rays);
    }
    job.rays += rays;
}

}  // namespace embree_peer
