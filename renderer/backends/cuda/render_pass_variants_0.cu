// Render-pass kernel variants 0–3 (sample_variants.h), compiled apart from the others.
#include "render_pass_kernel.cuh"

namespace trazo {

TRAZO_RENDER_PASS_VARIANT(0);
TRAZO_RENDER_PASS_VARIANT(1);
TRAZO_RENDER_PASS_VARIANT(2);
TRAZO_RENDER_PASS_VARIANT(3);

}  // namespace trazo
