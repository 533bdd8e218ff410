// Render-pass kernel variants 8–11 (sample_variants.h), compiled apart from the others.
#include "render_pass_kernel.cuh"

namespace trazo {

TRAZO_RENDER_PASS_VARIANT(8);
TRAZO_RENDER_PASS_VARIANT(9);
TRAZO_RENDER_PASS_VARIANT(10);
TRAZO_RENDER_PASS_VARIANT(11);

}  // namespace trazo
