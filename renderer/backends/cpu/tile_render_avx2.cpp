// The CPU backend's kernels built for AVX2 and FMA (compile flags: renderer/CMakeLists.txt).
#include "backends/cpu/tile_render.h"

namespace trazo {

namespace {
constexpr CpuKernels kKernels = makeCpuKernels(CpuIsa::Avx2, &cameraPacketKernelsAvx2);
}  // namespace

const CpuKernels& cpuKernelsAvx2() { return kKernels; }

}  // namespace trazo
