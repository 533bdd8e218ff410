// Render-pass kernel variant 17 (sample_variants.h): the path tracer of SPEC §7, its one instance; compiled
// apart from the thesis's.
#include "render_pass_kernel.cuh"

namespace trazo {

TRAZO_RENDER_PASS_VARIANT(17);

}  // namespace trazo
