// embree_render --mode stream: the form an Embree expert writes. Over 8×8-pixel tiles, the camera rays go
// as rtcIntersect16 (or 8, 4) packets of 4×4 (4×2, 2×2) pixels, then every shadow ray of the tile (up to
// 64 pixels × light points, 6 400 for a 10×10 light) goes to Embree in one stream call, rtcOccluded1M (an
// array of RTCRay; rtcOccludedNp, SoA, measured a few % slower), under RTC_INTERSECT_CONTEXT_FLAG_COHERENT.
// The shading is the single mode's own (embree_render.h): the light points are drawn in the same order from
// the same per-pixel stream and the terms summed in the same order, so the image is the single mode's.
#include <algorithm>

#include "embree_render.h"

namespace embree_peer {
namespace {

constexpr int kTile = 8, kTilePixels = kTile * kTile;

// A tile's pixels in Morton order, so N consecutive pixels (one packet) make a 4×4, 4×2 or 2×2 block.
struct MortonTile {
    int x[kTilePixels], y[kTilePixels];
    MortonTile() {
        for (int i = 0; i < kTilePixels; ++i) {
            x[i] = (i & 1) | ((i >> 1) & 2) | ((i >> 2) & 4);
            y[i] = ((i >> 1) & 1) | ((i >> 2) & 2) | ((i >> 3) & 4);
        }
    }
};
const MortonTile kMorton;

void intersect(const int* valid, RTCScene s, RTCIntersectContext* c, RTCRayHit4* r) { rtcIntersect4(valid, s, c, r); }
void intersect(const int* valid, RTCScene s, RTCIntersectContext* c, RTCRayHit8* r) { rtcIntersect8(valid, s, c, r); }
void intersect(const int* valid, RTCScene s, RTCIntersectContext* c, RTCRayHit16* r) { rtcIntersect16(valid, s, c, r); }

// The tile's camera rays, N per packet; pixels outside the image are invalid lanes.
template <int N, class RayHitN>
void traceCamera(const RenderJob& job, RTCIntersectContext* ctx, int x0, int y0, Surface* surface, bool* inside,
                 uint64_t& rays) {
    for (int first = 0; first < kTilePixels; first += N) {
        alignas(64) int valid[N];
        alignas(64) RayHitN rh{};
        for (int lane = 0; lane < N; ++lane) {
            const int i = first + lane, px = x0 + kMorton.x[i], py = y0 + kMorton.y[i];
            inside[i] = px < job.width && py < job.height;
            valid[lane] = inside[i] ? -1 : 0;
            const Vec3 dir = inside[i] ? cameraDirection(job, px, py) : job.forward;
            rh.ray.org_x[lane] = job.origin.x, rh.ray.org_y[lane] = job.origin.y, rh.ray.org_z[lane] = job.origin.z;
            rh.ray.dir_x[lane] = dir.x, rh.ray.dir_y[lane] = dir.y, rh.ray.dir_z[lane] = dir.z;
            rh.ray.tfar[lane] = INFINITY;
            rh.ray.mask[lane] = kMaskOccluder | kMaskLight;
            rh.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
        }
        intersect(valid, job.rtc, ctx, &rh);
        for (int lane = 0; lane < N; ++lane) {
            if (!valid[lane]) continue;
            ++rays;
            const Vec3 dir(rh.ray.dir_x[lane], rh.ray.dir_y[lane], rh.ray.dir_z[lane]);
            surface[first + lane] = surfaceAt(job, dir, rh.hit.geomID[lane], rh.hit.primID[lane], rh.ray.tfar[lane],
                                              Vec3(rh.hit.Ng_x[lane], rh.hit.Ng_y[lane], rh.hit.Ng_z[lane]));
        }
    }
}

// One tile's shadow rays, P → X, in the layout of the chosen stream call.
class ShadowRays {
public:
    explicit ShadowRays(ShadowStream kind) : kind_(kind) {}
    void clear() { count_ = 0; }
    int size() const { return count_; }

    void add(Vec3 from, Vec3 to) {
        const Vec3 d = to - from;
        if (kind_ == ShadowStream::OneM) {
            if ((size_t)count_ == aos_.size()) aos_.resize(std::max<size_t>(1024, 2 * aos_.size()));
            RTCRay& r = aos_[count_];
            r = RTCRay{};
            r.org_x = from.x, r.org_y = from.y, r.org_z = from.z;
            r.dir_x = d.x, r.dir_y = d.y, r.dir_z = d.z;
            r.tfar = kShadowTfar;
            r.mask = kMaskOccluder;
        } else {
            if ((size_t)count_ == soa_[0].size()) {  // tnear, time, mask, id and flags are the same for all
                for (std::vector<float>& a : soa_) a.resize(std::max<size_t>(1024, 2 * a.size()), 0.0f);
                mask_.resize(soa_[0].size(), kMaskOccluder), zeros_.resize(soa_[0].size(), 0u);
            }
            soa_[0][count_] = from.x, soa_[1][count_] = from.y, soa_[2][count_] = from.z;
            soa_[4][count_] = d.x, soa_[5][count_] = d.y, soa_[6][count_] = d.z;
            soa_[8][count_] = kShadowTfar;  // Embree sets it to -inf when occluded
        }
        ++count_;
    }

    void trace(RTCScene rtc, RTCIntersectContext* ctx) {
        if (count_ == 0) return;
        if (kind_ == ShadowStream::OneM) {
            rtcOccluded1M(rtc, ctx, aos_.data(), (unsigned)count_, sizeof(RTCRay));
            return;
        }
        const RTCRayNp rays{soa_[0].data(), soa_[1].data(), soa_[2].data(), soa_[3].data(), soa_[4].data(),
                            soa_[5].data(), soa_[6].data(), soa_[7].data(), soa_[8].data(), mask_.data(),
                            zeros_.data(), zeros_.data()};
        rtcOccludedNp(rtc, ctx, &rays, (unsigned)count_);
    }

    bool occluded(int i) const { return (kind_ == ShadowStream::OneM ? aos_[i].tfar : soa_[8][i]) < 0.0f; }
    Vec3 direction(int i) const {  // X - P, as add() stored it
        return kind_ == ShadowStream::OneM ? Vec3(aos_[i].dir_x, aos_[i].dir_y, aos_[i].dir_z)
                                           : Vec3(soa_[4][i], soa_[5][i], soa_[6][i]);
    }

private:
    static constexpr int kFloats = 9;  // org x y z, tnear, dir x y z, time, tfar: RTCRayNp's float arrays
    ShadowStream kind_;
    int count_ = 0;
    std::vector<RTCRay> aos_;
    std::vector<float> soa_[kFloats];
    std::vector<unsigned> mask_, zeros_;  // the masks, and the ids and flags (0)
};

}  // namespace

void renderTilesStream(RenderJob& job) {
    const int tilesX = (job.width + kTile - 1) / kTile, tilesY = (job.height + kTile - 1) / kTile;
    const int perPixel = termsPerPixel(job);
    RTCIntersectContext cameraCtx, shadowCtx;
    rtcInitIntersectContext(&cameraCtx);
    rtcInitIntersectContext(&shadowCtx);
    if (job.coherentCamera) cameraCtx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    if (job.coherentShadows) shadowCtx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    Surface surface[kTilePixels];
    bool inside[kTilePixels];
    std::vector<int> rayOfTerm((size_t)kTilePixels * perPixel);  // each pixel's terms' shadow rays, -1: none
    ShadowRays shadows(job.shadowStream);
    uint64_t rays = 0;
    for (int tile; (tile = job.nextTile++) < tilesX * tilesY;) {
        const int x0 = (tile % tilesX) * kTile, y0 = (tile / tilesX) * kTile;
        if (job.packet == 1) {
            for (int i = 0; i < kTilePixels; ++i) {
                const int px = x0 + kMorton.x[i], py = y0 + kMorton.y[i];
                if ((inside[i] = px < job.width && py < job.height)) surface[i] = cameraHit1(job, &cameraCtx, px, py), ++rays;
            }
        } else if (job.packet == 4) traceCamera<4, RTCRayHit4>(job, &cameraCtx, x0, y0, surface, inside, rays);
        else if (job.packet == 8) traceCamera<8, RTCRayHit8>(job, &cameraCtx, x0, y0, surface, inside, rays);
        else traceCamera<16, RTCRayHit16>(job, &cameraCtx, x0, y0, surface, inside, rays);

        shadows.clear();
        for (int i = 0; i < kTilePixels; ++i) {
            if (!inside[i] || !surface[i].lit) continue;
            const Surface& s = surface[i];
            size_t k = (size_t)i * perPixel;
            sumLights(job, x0 + kMorton.x[i], y0 + kMorton.y[i], [&](Vec3 x, Vec3) {
                const bool faces = facesLight(s, x - s.p);
                rayOfTerm[k++] = faces ? shadows.size() : -1;
                if (faces) shadows.add(s.p, x);
                return Vec3(0.0f);
            });
        }
        shadows.trace(job.rtc, &shadowCtx);
        rays += shadows.size();

        for (int i = 0; i < kTilePixels; ++i) {
            if (!inside[i]) continue;
            Vec3& pixel = (*job.image)[(size_t)(y0 + kMorton.y[i]) * job.width + x0 + kMorton.x[i]];
            if (!surface[i].lit) {
                pixel = surface[i].color;
                continue;
            }
            const int* ray = &rayOfTerm[(size_t)i * perPixel];
            pixel = sumTerms(job, [&](Vec3 color) {
                const int r = *ray++;
                return r < 0 || shadows.occluded(r) ? Vec3(0.0f) : unshadowedTerm(surface[i], shadows.direction(r), color);
            });
        }
    }
    job.rays += rays;
}

}  // namespace embree_peer
