// Render-pass kernel variants 4–7 (sample_variants.h), compiled apart from the others.
#include "render_pass_kernel.cuh"

namespace trazo {

template void launchRenderPass<variantFeatures(4)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                   AccumPixel*, unsigned long long*);
template void launchRenderPass<variantFeatures(5)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                   AccumPixel*, unsigned long long*);
template void launchRenderPass<variantFeatures(6)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                   AccumPixel*, unsigned long long*);
template void launchRenderPass<variantFeatures(7)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                   AccumPixel*, unsigned long long*);

}  // namespace trazo
