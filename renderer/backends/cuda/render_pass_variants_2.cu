// Render-pass kernel variants 8–11 (sample_variants.h), compiled apart from the others.
#include "render_pass_kernel.cuh"

namespace trazo {

template void launchRenderPass<variantFeatures(8)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                   AccumPixel*, unsigned long long*);
template void launchRenderPass<variantFeatures(9)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                   AccumPixel*, unsigned long long*);
template void launchRenderPass<variantFeatures(10)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                    AccumPixel*, unsigned long long*);
template void launchRenderPass<variantFeatures(11)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                    AccumPixel*, unsigned long long*);

}  // namespace trazo
