// The CPU backend's kernels built for AVX-512 F, DQ, BW and VL (compile flags: renderer/CMakeLists.txt).
#include "backends/cpu/tile_render.h"

namespace trazo {

namespace {
constexpr CpuKernels kKernels = makeCpuKernels(CpuIsa::Avx512, &cameraPacketKernelsAvx512);
}  // namespace

const CpuKernels& cpuKernelsAvx512() { return kKernels; }

}  // namespace trazo
