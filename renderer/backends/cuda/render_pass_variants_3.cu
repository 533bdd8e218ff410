// Render-pass kernel variants 12–15 (sample_variants.h), compiled apart from the others.
#include "render_pass_kernel.cuh"

namespace trazo {

template void launchRenderPass<variantFeatures(12)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                    AccumPixel*, unsigned long long*);
template void launchRenderPass<variantFeatures(13)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                    AccumPixel*, unsigned long long*);
template void launchRenderPass<variantFeatures(14)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                    AccumPixel*, unsigned long long*);
template void launchRenderPass<variantFeatures(15)>(dim3, dim3, const SceneView&, const FrameParams&, uint32_t,
                                                    AccumPixel*, unsigned long long*);

}  // namespace trazo
