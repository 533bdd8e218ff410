// The body of camera_tile_render_sse2/avx2/avx512.cpp: the CPU backend's tile renderer with camera packets,
// compiled as tile_render.h is (the same -m flags per ISA, -fno-weak, -ffp-contract=off) in translation units of
// its own (cpu_kernels.h says why). Include it nowhere else.
#pragma once

// Flattened, intersectScene's leaf copies a ShapeHit whose barycentrics only meshes set, and GCC then warns that
// they may be used uninitialised: they are read for mesh hits only. (Before the includes: the warning points there.)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "backends/cpu/cpu_kernels.h"
#include "integrator/sample_variants.h"
#if TRAZO_HOST_PACKETS
#include "integrator/thesis/camera_block.h"
#include "integrator/packets/camera_packet.h"
#endif

namespace trazo {
namespace {

#if TRAZO_HOST_PACKETS
#if !defined(TRAZO_FLATTEN_PACKET_KERNELS) || TRAZO_FLATTEN_PACKET_KERNELS
#define TRAZO_PACKET_KERNEL_FLATTEN __attribute__((flatten))
#else
#define TRAZO_PACKET_KERNEL_FLATTEN
#endif

constexpr uint32_t kPacketSide = 8;  // a block of kPacketSide² ≤ kPacketRays pixels traces its camera rays together
static_assert(kPacketSide * kPacketSide <= (uint32_t)kPacketRays, "a block's rays fit one packet");

// tile_render.h's renderTilePasses with each block's camera rays traced as one packet (tracePacket), where
// cameraPacketsApply, and for F that blockShadingServes the block's pixels shaded together (shadeBlock): the same
// samples, bit for bit. Per pixel the passes still add in pass order. flatten:
// everything the block loop calls is inlined into it (GCC's own choice left the shading and shadow rays out of
// line here: 5% more instructions on scene1_point). The sanitizer build turns it off (TRAZO_FLATTEN_PACKET_KERNELS,
// renderer/CMakeLists.txt): instrumented, these flattened kernels took most of that build's time.
template <IntegratorKind K, FeatureMask F>
TRAZO_PACKET_KERNEL_FLATTEN uint64_t renderTilePassesInPackets(const SceneView& scene, const FrameParams& frame,
                                                               Tile tile, uint32_t firstPass, uint32_t passCount,
                                                               AccumPixel* accum) {
    uint64_t rays = 0;
    RayPacket packet;
    TracedRay hits[kPacketRays];
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
            tracePacket(scene, frame.camera.origin, packet, active, hits);
            if constexpr (blockShadingServes<F>()) {  // the block's pixels shaded together (camera_block.h)
                PerRay<Vec3> color;
                uint32_t blockRays = 0;
                for (uint32_t pass = firstPass; pass < firstPass + passCount; ++pass) {
                    // Without indirect light every pass adds the same colours: shaded once.
                    if (pass == firstPass || !directOnlySample<F>())
                        blockRays = shadeBlock<F>(scene, frame, hits, imageX, imageY, active, pass, color.data());
                    for (uint64_t m = active; m; m &= m - 1) {
                        const int i = __builtin_ctzll(m);
                        accum[accumIndex[i]].add(color[i], frame.inSecondHalf(pass), frame.sampleWeight);
                    }
                    rays += blockRays;
                }
                continue;
            }
            for (uint32_t pass = firstPass; pass < firstPass + passCount; ++pass) {
                for (uint64_t m = active; m; m &= m - 1) {
                    const int i = __builtin_ctzll(m);
                    uint32_t sampleRays = 0;
                    const Vec3 c = renderSample<K, F>(scene, frame, imageX[i], imageY[i], pass, sampleRays, &hits[i]);
                    accum[accumIndex[i]].add(c, frame.inSecondHalf(pass), frame.sampleWeight);
                    rays += sampleRays;
                }
            }
        }
    }
    return rays;
}

// With indirect light only where the block is shaded together: elsewhere its camera rays are a small share of the
// rays, and packets there cost more than they saved (scene9_indirect_point: this translation unit's code for them
// inlined less of the indirect rays' work).
// The thesis's instances only: the block shading is its shading.
template <IntegratorKind K, FeatureMask F>
constexpr TileRenderFn packetTileRenderer() {
    if constexpr (K == IntegratorKind::Thesis && !((F & kFeatureIndirect) && !blockShadingServes<F>()))
        return &renderTilePassesInPackets<K, F>;
    else
        return nullptr;
}

template <IntegratorKind K, FeatureMask F>
struct PacketTileVariant {
    static constexpr TileRenderFn value = packetTileRenderer<K, F>();
};

void tracePacketEntry(const SceneView& scene, Vec3 origin, RayPacket& rays, uint64_t active, TracedRay* out) {
    tracePacket(scene, origin, rays, active, out);
}

constexpr CameraPacketKernels makeCameraPacketKernels() {
    constexpr auto tiles = makeVariantTable<PacketTileVariant>();
    CameraPacketKernels k{true, {}, &tracePacketEntry};
    for (uint32_t i = 0; i < kSampleVariantCount; ++i) k.renderTile[i] = tiles[i];
    return k;
}
#else
constexpr CameraPacketKernels makeCameraPacketKernels() { return CameraPacketKernels{false, {}, nullptr}; }
#endif

}  // namespace
}  // namespace trazo
