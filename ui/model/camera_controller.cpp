// Camera moves in spherical coordinates about the POI, +Y up (the renderer's own convention, camera_frame.h).
#include "model/camera_controller.h"

#include <algorithm>
#include <cmath>

#include "accel/collapse_bvh.h"
#include "integrator/camera_frame.h"

namespace trazo {
namespace {

constexpr float kDegrees = 3.14159265358979f / 180.0f;

// The camera's right and up axes exactly as the renderer builds them.
void cameraAxes(const Camera& c, Vec3& forward, Vec3& right, Vec3& up) {
    const CameraFrame f = makeCameraFrame(c.pov, c.poi, c.fovDegrees, 1, 1);
    forward = f.forward;
    right = f.right;
    up = f.up;
}

}  // namespace

float focalDistanceTo(const Camera& camera, Vec3 point) {
    const Vec3 view = camera.poi - camera.pov;
    const float length = std::sqrt(dot(view, view));
    if (!(length > 0.0f)) return 0.0f;
    return dot(point - camera.pov, view) / length;
}

Aabb sceneBounds(const SceneArrays& arrays) {
    Aabb b;
    if (!arrays.topNodes.empty()) b.grow(wideNodeBounds(arrays.topNodes[0]));
#define TRAZO_X(Data, array, ...) \
    for (const Data& l : arrays.array) b.grow(lightBounds(l));
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    return b;
}

void CameraController::orbit(Camera& camera, float dxPixels, float dyPixels) const {
    const Vec3 offset = camera.pov - camera.poi;
    const float distance = length(offset);
    if (distance <= 0.0f) return;
    float yaw = std::atan2(offset.x, offset.z);
    float pitch = std::asin(std::clamp(offset.y / distance, -1.0f, 1.0f));
    yaw -= dxPixels * s_.orbitRadiansPerPixel;  // drag right: the scene turns right, the camera goes left
    pitch = std::clamp(pitch + dyPixels * s_.orbitRadiansPerPixel, -s_.maxPitchRadians, s_.maxPitchRadians);
    camera.pov = camera.poi + Vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)) *
                                  distance;
}

void CameraController::pan(Camera& camera, float dxPixels, float dyPixels, float viewportHeight) const {
    Vec3 forward, right, up;
    cameraAxes(camera, forward, right, up);
    const float distance = length(camera.pov - camera.poi);
    // World units per screen pixel at the POI's depth.
    const float perPixel = 2.0f * distance * std::tan(0.5f * camera.fovDegrees * kDegrees) / std::max(viewportHeight, 1.0f);
    const Vec3 move = right * (-dxPixels * perPixel) + up * (dyPixels * perPixel);
    camera.pov += move;
    camera.poi += move;
}

void CameraController::dolly(Camera& camera, float notches) const {
    const Vec3 offset = camera.pov - camera.poi;
    const float distance = length(offset);
    if (distance <= 0.0f) return;
    const float next = std::max(distance * std::pow(s_.dollyFactorPerNotch, notches), s_.minDistance);
    camera.pov = camera.poi + offset * (next / distance);
}

void CameraController::fly(Camera& camera, float forward, float right, float up, float seconds) const {
    Vec3 f, r, u;
    cameraAxes(camera, f, r, u);
    const float step = std::max(length(camera.pov - camera.poi), s_.minDistance) * s_.flyFractionPerSecond * seconds;
    const Vec3 move = (f * forward + r * right + Vec3(0, 1, 0) * up) * step;
    camera.pov += move;
    camera.poi += move;
}

void CameraController::frame(Camera& camera, const Aabb& bounds) const {
    if (bounds.empty()) return;
    const Vec3 centre = bounds.centroid();
    const float radius = std::max(0.5f * length(bounds.extent()), s_.minDistance);
    Vec3 direction = camera.pov - camera.poi;
    direction = lengthSquared(direction) > 0.0f ? normalize(direction) : Vec3(0, 0, 1);
    // The bounding sphere fits the vertical field of view (the narrower one for landscape images).
    const float halfFov = std::max(0.5f * camera.fovDegrees * kDegrees, 1e-3f);
    camera.poi = centre;
    camera.pov = centre + direction * (radius / std::sin(halfFov));
}

}  // namespace trazo
