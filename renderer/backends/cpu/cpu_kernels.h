// The CPU backend's hot code as a table of functions, compiled once per instruction set (tile_render_*.cpp
// from tile_render.h) and chosen at start-up (cpu_isa.cpp): the tile renderer, the ray-query loop and the
// shadow-ray and camera-ray packet queries. Host only.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "core/accumulation.h"
#include "integrator/frame_params.h"
#include "integrator/ray_query.h"
#include "integrator/sample_variants.h"

namespace trazo {

struct RayPacket;  // integrator/packets/packet_lanes.h
struct TracedRay;  // integrator/scene_intersect.h

enum class CpuIsa : uint32_t { Sse2, Avx2, Avx512 };
constexpr CpuIsa kCpuIsas[] = {CpuIsa::Sse2, CpuIsa::Avx2, CpuIsa::Avx512};

struct Tile {
    uint32_t x0, y0, x1, y1;
};

// Adds the passes' samples of the tile's pixels to accum (the image's row-major AccumPixels); returns rays.
using TileRenderFn = uint64_t (*)(const SceneView& scene, const FrameParams& frame, Tile tile, uint32_t firstPass,
                                  uint32_t passCount, AccumPixel* accum);

// The tile renderers that trace each 8×8 block's camera rays as one packet (camera_tile_render.h), for scenes
// where cameraPacketsApply, and the packet query they use. Compiled in translation units of their own
// (camera_tile_render_*.cpp): beside tile_render.h's code they changed GCC's inlining of it (scene9_indirect_point
// 4% more instructions).
struct CameraPacketKernels {
    bool available;  // false in the device-paths build, which has no packets
    std::array<TileRenderFn, kSampleVariantCount> renderTile;  // by sampleVariantFor(features); null: not for it
    // tracePacket (integrator/packets/nearest_packet.h) at this ISA's width.
    void (*tracePacket)(const SceneView& scene, Vec3 origin, RayPacket& rays, uint64_t active, TracedRay* out);
};
const CameraPacketKernels& cameraPacketKernelsSse2();
const CameraPacketKernels& cameraPacketKernelsAvx2();
const CameraPacketKernels& cameraPacketKernelsAvx512();

// Whether a scene's camera rays are traced in packets: one camera ray per pixel and pass (renderSample's given
// hits are then one per pixel), from one origin (a pinhole: a lens gives each ray its own), and no meshes or
// CSG solids, whose rays would all be traced again.
inline bool cameraPacketsApply(const SceneView& scene) {
    return antialiasingSide(scene.settings.antialiasing) == 1 && scene.settings.aperture == 0.0f &&
           scene.topNodes.count > 0 && scene.meshes.count == 0 && scene.csgs.count == 0;
}

struct CpuKernels {
    CpuIsa isa;
    std::array<TileRenderFn, kSampleVariantCount> renderTile;  // by sampleVariantFor(features)
    // out[i] = answerRayQuery(scene, queries[i], kind) for i < count.
    void (*answerRayQueries)(const SceneView& scene, const RayQuery* queries, size_t count, RayQueryKind kind,
                             RayAnswer* out);
    // occludedPacket (integrator/packets/occluded_packet.h) at this ISA's width; null in the device-paths build.
    uint64_t (*occludedPacket)(const SceneView& scene, Vec3 origin, const RayPacket& rays, uint64_t active);
    // The camera-packet kernels of this ISA.
    const CameraPacketKernels& (*cameraPackets)();
};

// One per translation unit: tile_render_sse2.cpp (baseline x86-64), _avx2.cpp (AVX2 + FMA), _avx512.cpp
// (AVX-512 F/DQ/BW/VL). Only call one whose ISA cpuIsaSupported() says the CPU has.
const CpuKernels& cpuKernelsSse2();
const CpuKernels& cpuKernelsAvx2();
const CpuKernels& cpuKernelsAvx512();

const char* cpuIsaName(CpuIsa isa);  // "sse2", "avx2", "avx512"
bool cpuIsaSupported(CpuIsa isa);    // this CPU (and OS) runs it, and this build has it
// The kernels of an ISA the CPU supports, or null.
const CpuKernels* cpuKernelsFor(CpuIsa isa);
// The widest supported ISA, unless the environment variable TRAZO_CPU_ISA (sse2, avx2 or avx512) names one:
// then that one if supported, else the widest with a warning on stderr (once).
const CpuKernels& selectCpuKernels();

}  // namespace trazo
