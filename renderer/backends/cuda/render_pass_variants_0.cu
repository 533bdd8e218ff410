// Render-pass kernel variants 0–3 (sample_variants.h), compiled apart from the others.
#include "render_pass_kernel.cuh"

namespace trazo {

template void launchRenderPass<variantFeatures(0)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                   AccumPixel*, unsigned long long*);
template void launchRenderPass<variantFeatures(1)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                   AccumPixel*, unsigned long long*);
template void launchRenderPass<variantFeatures(2)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                   AccumPixel*, unsigned long long*);
template void launchRenderPass<variantFeatures(3)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                   AccumPixel*, unsigned long long*);

}  // namespace trazo
