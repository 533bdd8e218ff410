// What the backend needs of the render-pass kernel: its block shape and one launcher per specialised variant,
// each compiled in its own translation unit (render_pass_variants_*.cu) so a build compiles the variants on
// every core. Only those units include the kernel itself (render_pass_kernel.cuh).
#pragma once

#include <cuda_runtime.h>

#include "integrator/sample_variants.h"
#include "core/accumulation.h"

namespace trazo {

// Passes launch in 16×16 blocks: whole warps, as the kernel's warp-shuffle ray count needs.
constexpr unsigned kPassBlockX = 16, kPassBlockY = 16;
static_assert((kPassBlockX * kPassBlockY) % 32 == 0, "renderPassKernel's ray count shuffles over full warps");

template <IntegratorKind K, FeatureMask F>
void launchRenderPass(dim3 grid, dim3 block, const SceneView& scene, const FrameParams& frame, uint32_t pass,
                      AccumPixel* accum, unsigned long long* rayCounter);

}  // namespace trazo
