// The CPU backend's kernels built for baseline x86-64 (compile flags: renderer/CMakeLists.txt).
#include "backends/cpu/tile_render.h"

namespace trazo {

namespace {
constexpr CpuKernels kKernels = makeCpuKernels(CpuIsa::Sse2, &cameraPacketKernelsSse2);
}  // namespace

const CpuKernels& cpuKernelsSse2() { return kKernels; }

}  // namespace trazo
