// Host only: the camera rays of up to 64 pixels aimed together, to be traced as one packet (nearest_packet.h's
// tracePacket: they share the pinhole as origin) for an integrator's given hit.
#pragma once

#include "integrator/camera_frame.h"
#include "integrator/camera_ray.h"
#include "integrator/packets/nearest_packet.h"

namespace trazo {

// cameraRay's ray of pixel (px, py) when the antialiasing side is 1: its one position, the centre.
inline Ray centreCameraRay(const CameraFrame& camera, uint32_t px, uint32_t py) {
    float x, y;
    antialiasingPosition(1, 0, px, py, x, y);
    return generateCameraRay(camera, x, y);
}

// Lane by lane, centreCameraRay's direction through pixel (pixelX[i], pixelY[i]) into out's ray i:
// generateCameraRay's operations in the same order, at the centre float(p) + 0.5 of antialiasingPosition(1, 0).
inline void aimCameraRays(const CameraFrame& c, const float* pixelX, const float* pixelY, RayPacket& out) {
    using namespace packet_detail;
    for (int g = 0; g < kGroups; ++g) {
        const int o = g * kLanes;
        const LaneF x = load(pixelX + o) + 0.5f, y = load(pixelY + o) + 0.5f;
        const LaneF sx = (2.0f * x / float(c.width) - 1.0f) * c.tanHalfFovY * c.aspect;
        const LaneF sy = (1.0f - 2.0f * y / float(c.height)) * c.tanHalfFovY;
        const V3 v = {c.forward.x + c.right.x * sx + c.up.x * sy, c.forward.y + c.right.y * sx + c.up.y * sy,
                      c.forward.z + c.right.z * sx + c.up.z * sy};
        const LaneF inv = 1.0f / sqrt(dot(v, v));
        const LaneF dx = v.x * inv, dy = v.y * inv, dz = v.z * inv;
        std::memcpy(out.dx + o, &dx, sizeof dx);
        std::memcpy(out.dy + o, &dy, sizeof dy);
        std::memcpy(out.dz + o, &dz, sizeof dz);
    }
}

}  // namespace trazo
