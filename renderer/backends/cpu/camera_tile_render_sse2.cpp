// The CPU backend's camera-packet kernels built for baseline x86-64 (SSE2) (compile flags: renderer/CMakeLists.txt).
#include "backends/cpu/camera_tile_render.h"

namespace trazo {

namespace {
constexpr CameraPacketKernels kKernels = makeCameraPacketKernels();
}  // namespace

const CameraPacketKernels& cameraPacketKernelsSse2() { return kKernels; }

}  // namespace trazo
