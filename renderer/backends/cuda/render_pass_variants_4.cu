// Render-pass kernel variant 16 (sample_variants.h): every feature, SPEC §6's dispersion and subsurface
// scattering included; compiled apart from the others.
#include "render_pass_kernel.cuh"

namespace trazo {

TRAZO_RENDER_PASS_VARIANT(16);

}  // namespace trazo
