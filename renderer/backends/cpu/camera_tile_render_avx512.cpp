// The CPU backend's camera-packet kernels built for AVX-512 F/DQ/BW/VL (compile flags: renderer/CMakeLists.txt).
#include "backends/cpu/camera_tile_render.h"

namespace trazo {

namespace {
constexpr CameraPacketKernels kKernels = makeCameraPacketKernels();
}  // namespace

const CameraPacketKernels& cameraPacketKernelsAvx512() { return kKernels; }

}  // namespace trazo
