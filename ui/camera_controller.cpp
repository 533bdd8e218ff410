// Camera moves in spherical coordinates about the POI, +Y up (the renderer's own convention, camera_frame.h).
#include "camera_controller.h"

#include <algorithm>
#include <cmath>

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

void addTransformed(Bounds& b, const std::vector<TransformStep>& steps, Vec3 lo, Vec3 hi) {
    const Affine3 m = composeTransforms(steps);
    for (int i = 0; i < 8; ++i) {
        const Vec3 corner{(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
        b.add(m.applyToPoint(corner));
    }
}

}  // namespace

Bounds sceneBounds(const Scene& scene) {
    Bounds b;
    for (const Sphere& s : scene.spheres) {
        b.add(s.center - Vec3(s.radius));
        b.add(s.center + Vec3(s.radius));
    }
    for (const Box& box : scene.boxes) addTransformed(b, box.transforms, Vec3(-0.5f), Vec3(0.5f));
    for (const Cylinder& c : scene.cylinders) {
        const Vec3 top = c.base + normalize(c.axis) * c.height;
        for (Vec3 end : {c.base, top}) {
            b.add(end - Vec3(c.radius));
            b.add(end + Vec3(c.radius));
        }
    }
    for (const Mesh& mesh : scene.meshes) {
        if (!mesh.data) continue;
        const Affine3 m = composeTransforms(mesh.transforms);
        for (const Vec3& p : mesh.data->positions) b.add(m.applyToPoint(p));
    }
    // A CSG solid lies within its primitives (a loose box is enough to frame it).
    for (const Csg& csg : scene.csgs) {
        if (!csg.tree) continue;
        Bounds local;
        for (const CsgNode& n : csg.tree->nodes) {
            if (n.kind == CsgNode::Kind::Sphere) {
                addTransformed(local, n.transforms, n.center - Vec3(n.radius), n.center + Vec3(n.radius));
            } else if (n.kind == CsgNode::Kind::Box) {
                addTransformed(local, n.transforms, Vec3(-0.5f), Vec3(0.5f));
            } else if (n.kind == CsgNode::Kind::Cylinder) {
                const Vec3 top = n.base + normalize(n.axis) * n.height;
                addTransformed(local, n.transforms, min(n.base, top) - Vec3(n.radius), max(n.base, top) + Vec3(n.radius));
            }
        }
        if (!local.empty()) addTransformed(b, csg.transforms, local.lo, local.hi);
    }
    for (const PointLight& l : scene.pointLights) b.add(l.position);
    for (const AreaLight& l : scene.areaLights) b.add(l.position);
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

void CameraController::frame(Camera& camera, const Bounds& bounds) const {
    if (bounds.empty()) return;
    const Vec3 centre = (bounds.lo + bounds.hi) * 0.5f;
    const float radius = std::max(0.5f * length(bounds.hi - bounds.lo), s_.minDistance);
    Vec3 direction = camera.pov - camera.poi;
    direction = lengthSquared(direction) > 0.0f ? normalize(direction) : Vec3(0, 0, 1);
    // The bounding sphere fits the vertical field of view (the narrower one for landscape images).
    const float halfFov = std::max(0.5f * camera.fovDegrees * kDegrees, 1e-3f);
    camera.poi = centre;
    camera.pov = centre + direction * (radius / std::sin(halfFov));
}

}  // namespace trazo
