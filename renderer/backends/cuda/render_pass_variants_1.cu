// Render-pass kernel variants 4–7 (sample_variants.h), compiled apart from the others.
#include "render_pass_kernel.cuh"

namespace trazo {

TRAZO_RENDER_PASS_VARIANT(4);
TRAZO_RENDER_PASS_VARIANT(5);
TRAZO_RENDER_PASS_VARIANT(6);
TRAZO_RENDER_PASS_VARIANT(7);

}  // namespace trazo
