// Host only: the camera rays of up to 64 pixels traced together (nearestPacket: they share the pinhole as
// origin), each completed to the CameraHit that intersectScene would give it, for renderSample's given hit.
#pragma once

#include "integrator/camera_frame.h"
#include "integrator/nearest_packet.h"
#include "integrator/render_sample.h"

namespace trazo {

// renderSample's camera ray of pixel (px, py) when the antialiasing side is 1: its one position, the centre.
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

// The rays of `active` in `rays` (directions; tMax INFINITY, overwritten) from the camera's origin: out[i] is
// ray i and intersectScene(scene, ray i, INFINITY)'s answer.
inline void traceCameraPacket(const SceneView& scene, Vec3 origin, RayPacket& rays, uint64_t active, CameraHit* out) {
    NearestHits nearest;
    nearestPacket(scene, origin, rays, active, nearest);
    uint32_t faceObject = kNoObject;  // the box face whose normal was computed last: most rays of a block share it
    int lastFace = -1;
    Vec3 faceNormal;
    for (uint64_t m = active; m; m &= m - 1) {
        const int i = __builtin_ctzll(m);
        const Ray ray{origin, Vec3(rays.dx[i], rays.dy[i], rays.dz[i])};
        CameraHit& c = out[i];
        c.ray = ray;
        const uint32_t object = nearest.object[i];
        const ObjectKind kind = object != kNoObject ? scene.objects[object].kind : ObjectKind::Sphere;
        // Ties, and the rays whose nearest object is a cylinder (the lanes keep no cylinder normal), take
        // intersectScene whole.
        if ((nearest.redo & (1ull << i)) || (kind != ObjectKind::Box && kind != ObjectKind::Sphere)) {
            c.found = intersectScene(scene, ray, INFINITY, c.hit);
            continue;
        }
        float tMax = INFINITY;
        c.found = false;
        if (object != kNoObject) {
            const ObjectRef& o = scene.objects[object];
            ShapeHit h{};
            if (o.kind == ObjectKind::Box) {  // intersectBox's normal of the face the lanes found
                const int face = nearest.boxFace[i];
                if (object != faceObject || face != lastFace) {
                    const Vec3 row = scene.boxes[o.index].objectFromWorld.row[face >> 1];
                    faceNormal = normalize(row * (face & 1 ? 1.0f : -1.0f));
                    faceObject = object;
                    lastFace = face;
                }
                h.t = nearest.t[i];
                h.normal = faceNormal;
            } else {  // a sphere: the lanes computed intersectSphere's normal
                h.t = nearest.t[i];
                h.normal = Vec3(nearest.nx[i], nearest.ny[i], nearest.nz[i]);
            }
            c.hit = SurfaceHit{h.t, h.normal, object, 0, h.triangle, h.b1, h.b2};
            tMax = h.t;
            c.found = true;
        }
        if (intersectAreaLights(scene, ray, tMax, c.hit)) c.found = true;
    }
}

}  // namespace trazo
