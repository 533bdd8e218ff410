// The render-pass kernel (one thread per pixel, one launch per pass) and its host launcher, for the variant
// translation units render_pass_variants_*.cu: each instantiates four of the 16 specialised variants, the
// last one the 17th.
#pragma once

#include "backends/cuda/render_pass_launch.h"

namespace trazo {

// Two blocks per SM: at most 128 registers a thread, 16 warps an SM (an H100 holds 64K registers an SM).
// TRAZO_CUDA_PASS_MIN_BLOCKS=1 (CMake) lifts the cap, for timing the trade on a GPU.
#if !defined(TRAZO_CUDA_PASS_MIN_BLOCKS)
#define TRAZO_CUDA_PASS_MIN_BLOCKS 2
#endif

template <IntegratorKind K, FeatureMask F>
__global__ void __launch_bounds__(kPassBlockX* kPassBlockY, TRAZO_CUDA_PASS_MIN_BLOCKS) renderPassKernel(SceneView scene, FrameParams frame, uint32_t pass, AccumPixel* accum,
                                 unsigned long long* rayCounter) {
    const uint32_t x = blockIdx.x * blockDim.x + threadIdx.x;
    const uint32_t y = blockIdx.y * blockDim.y + threadIdx.y;
    uint32_t rays = 0;
    uint32_t px, py;  // accumulation pixel (x, y) is image pixel (px, py): the image's own, or the probe's list
    if (x < frame.accumWidth() && y < frame.accumHeight() && frame.imagePixel(x, y, px, py)) {
        const Vec3 c = renderSample<K, F>(scene, frame, px, py, pass, rays);
        accum[(size_t)y * frame.accumWidth() + x].add(c, frame.inSecondHalf(pass), frame.sampleWeight);
    }
    // One atomic per warp for the ray count.
    for (int offset = 16; offset > 0; offset /= 2) rays += __shfl_down_sync(0xffffffffu, rays, offset);
    if ((threadIdx.x + threadIdx.y * blockDim.x) % 32 == 0 && rays) atomicAdd(rayCounter, (unsigned long long)rays);
}

// The launchers render_pass_launch.h declares.
template <IntegratorKind K, FeatureMask F>
void launchRenderPass(dim3 grid, dim3 block, const SceneView& scene, const FrameParams& frame, uint32_t pass,
                      AccumPixel* accum, unsigned long long* rayCounter) {
    renderPassKernel<K, F><<<grid, block>>>(scene, frame, pass, accum, rayCounter);
}

// Compiles variant I of the shared table (sample_variants.h) in the translation unit that says it.
#define TRAZO_RENDER_PASS_VARIANT(I)                                                                      \
    template void launchRenderPass<sampleVariant(I).integrator, sampleVariant(I).features>(              \
        dim3, dim3, const SceneView&, const FrameParams&, uint32_t, AccumPixel*, unsigned long long*)

}  // namespace trazo
