// The CPU backend's camera-packet kernels built for AVX2 and FMA (compile flags: renderer/CMakeLists.txt).
#include "backends/cpu/camera_tile_render.h"

namespace trazo {

namespace {
constexpr CameraPacketKernels kKernels = makeCameraPacketKernels();
}  // namespace

const CameraPacketKernels& cameraPacketKernelsAvx2() { return kKernels; }

}  // namespace trazo
