// The pinhole camera of SPEC §3 as kernels use it: vertical FOV, +Y up, pixel (0,0) top-left. SPEC §6's lens is
// the scene's (RenderSettings): integrator/thin_lens.h moves these rays' origins onto it.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/ray.h"

namespace trazo {

struct CameraFrame {
    Vec3 origin;
    Vec3 forward, right, up;  // orthonormal, right-handed (right = forward × up)
    float tanHalfFovY;
    float aspect;  // width / height
    uint32_t width, height;
};

inline CameraFrame makeCameraFrame(Vec3 pov, Vec3 poi, float fovDegrees, uint32_t width, uint32_t height) {
    CameraFrame f{};
    f.origin = pov;
    f.forward = normalize(poi - pov);
    // Up is +Y, or +Z when looking (almost) straight up or down.
    const Vec3 worldUp = fabsf(f.forward.y) > 0.9999f ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
    f.right = normalize(cross(f.forward, worldUp));
    f.up = cross(f.right, f.forward);
    f.tanHalfFovY = tanf(0.5f * fovDegrees * 3.14159265358979f / 180.0f);
    f.aspect = float(width) / float(height);
    f.width = width;
    f.height = height;
    return f;
}

// Ray through image position (x, y) in pixels, measured from the top-left corner of the image.
TRAZO_HD Ray generateCameraRay(const CameraFrame& c, float x, float y) {
    const float sx = (2.0f * x / float(c.width) - 1.0f) * c.tanHalfFovY * c.aspect;
    const float sy = (1.0f - 2.0f * y / float(c.height)) * c.tanHalfFovY;
    return Ray{c.origin, normalize(c.forward + c.right * sx + c.up * sy)};
}

}  // namespace trazo
