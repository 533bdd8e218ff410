// The body of tile_render_sse2/avx2/avx512.cpp (generated from tile_render_isa.cpp.in): the CPU backend's tile
// renderer and ray-query loop, compiled in each of those translation units with its own -m flags
// (renderer/CMakeLists.txt). Include it nowhere else. Each includer is compiled with -fno-weak, so every inline
// function and template it emits (renderSample and all it calls) is local to it: a baseline caller never links to
// an AVX copy. And with -ffp-contract=off, so that no a·b + c becomes a fused multiply-add: every path computes
// the same bits.
#pragma once

#include "backends/cpu/cpu_kernels.h"
#include "integrator/ray_query.h"
#include "integrator/sample_variants.h"
#if TRAZO_HOST_PACKETS
#include "integrator/packets/occluded_packet.h"
#endif

namespace trazo {
namespace {

// Passes inside the tile keep its data in cache; per pixel they still add in pass order. The tile is in the
// accumulation's pixels (frame.target). Returns rays.
template <IntegratorKind K, FeatureMask F>
uint64_t renderTilePasses(const SceneView& scene, const FrameParams& frame, Tile tile, uint32_t firstPass,
                          uint32_t passCount, AccumPixel* accum) {
    uint64_t rays = 0;
    for (uint32_t pass = firstPass; pass < firstPass + passCount; ++pass) {
        for (uint32_t y = tile.y0; y < tile.y1; ++y) {
            for (uint32_t x = tile.x0; x < tile.x1; ++x) {
                uint32_t sampleRays = 0;
                uint32_t px, py;  // the accumulation's pixel (x, y) is image pixel (px, py): frame.target
                if (!frame.imagePixel(x, y, px, py)) continue;
                const Vec3 c = renderSample<K, F>(scene, frame, px, py, pass, sampleRays);
                accum[(size_t)y * frame.accumWidth() + x].add(c, frame.inSecondHalf(pass), frame.sampleWeight);
                rays += sampleRays;
            }
        }
    }
    return rays;
}

template <IntegratorKind K, FeatureMask F>
struct TileVariant {
    static constexpr TileRenderFn value = &renderTilePasses<K, F>;
};

void answerRayQueries(const SceneView& scene, const RayQuery* queries, size_t count, RayQueryKind kind, RayAnswer* out) {
    for (size_t i = 0; i < count; ++i) out[i] = answerRayQuery(scene, queries[i], kind);
}

#if TRAZO_HOST_PACKETS
uint64_t occludedPacketEntry(const SceneView& scene, Vec3 origin, const RayPacket& rays, uint64_t active) {
    return occludedPacket(scene, origin, rays, active);
}
#endif

// cameraPackets: the camera-packet kernels of the same ISA (camera_tile_render.h).
constexpr CpuKernels makeCpuKernels(CpuIsa isa, const CameraPacketKernels& (*cameraPackets)()) {
    constexpr auto tiles = makeVariantTable<TileVariant>();
    CpuKernels k{isa, {}, &answerRayQueries, nullptr, cameraPackets};
    for (uint32_t i = 0; i < kSampleVariantCount; ++i) k.renderTile[i] = tiles[i];
#if TRAZO_HOST_PACKETS
    k.occludedPacket = &occludedPacketEntry;
#endif
    return k;
}

}  // namespace
}  // namespace trazo
