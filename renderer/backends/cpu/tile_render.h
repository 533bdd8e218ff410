// The body of tile_render_sse2/avx2/avx512.cpp: the CPU backend's tile renderer and ray-query loop, compiled
// in each of those translation units with its own -m flags (renderer/CMakeLists.txt). Include it nowhere
// else. Each includer is compiled with -fno-weak, so every inline function and template it emits (renderSample
// and all it calls) is local to it: a baseline caller never links to an AVX copy. And with
// -ffp-contract=off, so that no a·b + c becomes a fused multiply-add: every path computes the same bits.
#pragma once

#include "backends/cpu/cpu_kernels.h"
#include "integrator/ray_query.h"
#include "integrator/sample_variants.h"
#if TRAZO_SHADOW_PACKETS
#include "integrator/camera_packet.h"
#endif

namespace trazo {
namespace {

#if TRAZO_SHADOW_PACKETS
constexpr uint32_t kPacketSide = 8;  // a block of kPacketSide² ≤ kPacketRays pixels traces its camera rays together
static_assert(kPacketSide * kPacketSide <= (uint32_t)kPacketRays, "a block's rays fit one packet");

// renderTilePasses with each block's camera rays traced as one packet (traceCameraPacket), where
// cameraPacketsApply: the same samples, bit for bit.
template <FeatureMask F>
uint64_t renderTilePassesInPackets(const SceneView& scene, const FrameParams& frame, Tile tile, uint32_t firstPass,
                                   uint32_t passCount, AccumPixel* accum) {
    uint64_t rays = 0;
    RayPacket packet;
    CameraHit hits[kPacketRays];
    uint32_t imageX[kPacketRays], imageY[kPacketRays], accumIndex[kPacketRays];
    alignas(64) float pixelX[kPacketRays], pixelY[kPacketRays];
    for (uint32_t by = tile.y0; by < tile.y1; by += kPacketSide) {
        for (uint32_t bx = tile.x0; bx < tile.x1; bx += kPacketSide) {
            // The block's rays are the same in every pass (one position, the pixel's centre).
            uint64_t active = 0;
            int lane = 0;
            for (int i = 0; i < kPacketRays; ++i) pixelX[i] = pixelY[i] = 0.0f;
            for (uint32_t y = by; y < by + kPacketSide && y < tile.y1; ++y) {
                for (uint32_t x = bx; x < bx + kPacketSide && x < tile.x1; ++x, ++lane) {
                    uint32_t px, py;  // the accumulation's pixel (x, y) is image pixel (px, py): frame.target
                    if (!frame.imagePixel(x, y, px, py)) continue;
                    pixelX[lane] = float(px);
                    pixelY[lane] = float(py);
                    imageX[lane] = px;
                    imageY[lane] = py;
                    accumIndex[lane] = y * frame.accumWidth() + x;
                    active |= 1ull << lane;
                }
            }
            aimCameraRays(frame.camera, pixelX, pixelY, packet);  // centreCameraRay of each pixel
            for (int i = 0; i < kPacketRays; ++i) packet.tMax[i] = INFINITY;
            traceCameraPacket(scene, frame.camera.origin, packet, active, hits);
            for (uint32_t pass = firstPass; pass < firstPass + passCount; ++pass) {
                for (uint64_t m = active; m; m &= m - 1) {
                    const int i = __builtin_ctzll(m);
                    uint32_t sampleRays = 0;
                    const Vec3 c = renderSample<F, true>(scene, frame, imageX[i], imageY[i], pass, sampleRays, &hits[i]);
                    accum[accumIndex[i]].add(c, frame.inSecondHalf(pass), frame.sampleWeight);
                    rays += sampleRays;
                }
            }
        }
    }
    return rays;
}
#endif

// Passes inside the tile keep its data in cache; per pixel they still add in pass order. The tile is in the
// accumulation's pixels (frame.target). Returns rays.
template <FeatureMask F>
uint64_t renderTilePasses(const SceneView& scene, const FrameParams& frame, Tile tile, uint32_t firstPass,
                          uint32_t passCount, AccumPixel* accum) {
#if TRAZO_SHADOW_PACKETS
    if (cameraPacketsApply(scene)) return renderTilePassesInPackets<F>(scene, frame, tile, firstPass, passCount, accum);
#endif
    uint64_t rays = 0;
    for (uint32_t pass = firstPass; pass < firstPass + passCount; ++pass) {
        for (uint32_t y = tile.y0; y < tile.y1; ++y) {
            for (uint32_t x = tile.x0; x < tile.x1; ++x) {
                uint32_t sampleRays = 0;
                uint32_t px, py;  // the accumulation's pixel (x, y) is image pixel (px, py): frame.target
                if (!frame.imagePixel(x, y, px, py)) continue;
                const Vec3 c = renderSample<F>(scene, frame, px, py, pass, sampleRays);
                accum[(size_t)y * frame.accumWidth() + x].add(c, frame.inSecondHalf(pass), frame.sampleWeight);
                rays += sampleRays;
            }
        }
    }
    return rays;
}

template <FeatureMask F>
struct TileVariant {
    static constexpr TileRenderFn value = &renderTilePasses<F>;
};

void answerRayQueries(const SceneView& scene, const RayQuery* queries, size_t count, RayQueryKind kind, RayAnswer* out) {
    for (size_t i = 0; i < count; ++i) out[i] = answerRayQuery(scene, queries[i], kind);
}

#if TRAZO_SHADOW_PACKETS
uint64_t occludedPacketEntry(const SceneView& scene, Vec3 origin, const RayPacket& rays, uint64_t active) {
    return occludedPacket(scene, origin, rays, active);
}
void traceCameraPacketEntry(const SceneView& scene, Vec3 origin, RayPacket& rays, uint64_t active, CameraHit* out) {
    traceCameraPacket(scene, origin, rays, active, out);
}
#endif

constexpr CpuKernels makeCpuKernels(CpuIsa isa) {
    constexpr auto tiles = makeVariantTable<TileVariant>();
    CpuKernels k{isa, {}, &answerRayQueries, nullptr, nullptr};
    for (uint32_t i = 0; i < kSampleVariantCount; ++i) k.renderTile[i] = tiles[i];
#if TRAZO_SHADOW_PACKETS
    k.occludedPacket = &occludedPacketEntry;
    k.traceCameraPacket = &traceCameraPacketEntry;
#endif
    return k;
}

}  // namespace
}  // namespace trazo
