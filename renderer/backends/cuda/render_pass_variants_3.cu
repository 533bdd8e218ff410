// Render-pass kernel variants 12–15 (sample_variants.h), compiled apart from the others.
#include "render_pass_kernel.cuh"

namespace trazo {

TRAZO_RENDER_PASS_VARIANT(12);
TRAZO_RENDER_PASS_VARIANT(13);
TRAZO_RENDER_PASS_VARIANT(14);
TRAZO_RENDER_PASS_VARIANT(15);

}  // namespace trazo
