// What shading needs at a hit, beyond the hit itself: the shading normal (interpolated on meshes, then
// normal-mapped), texture coordinates and tangent frame, and the material with its textures applied
// (SPEC §5: Kd, Ks, Ke are the material colours times their textures).
#pragma once

#include "geometry/surface_frame.h"
#include "integrator/scene_intersect.h"
#include "shading/shading_point.h"
#include "shading/material.h"
#include "shading/texture.h"

namespace trazo {

// wantUv: the material has textures (materialHasTextures); without, the uv and tangent frame (an atan2 and an
// acos on a sphere) are skipped: applyTextures would not read them.
TRAZO_HD SurfacePoint surfaceAt(const SceneView& scene, const ObjectRef& o, const SurfaceHit& hit, Vec3 p, bool wantUv) {
    const ShapeHit shapeHit = shapeHitOf(hit);
    return visitObject(scene, o, [&](const auto& shape) { return objectSurface(scene, shape, shapeHit, p, wantUv); });
}

// Where an object's hit along `ray` is, with its error bound: the object kind's own computation from its surface
// (objectHitPoint), so secondary rays leave by an offset that scales with the hit, not with the ray's origin.
// hit.normal becomes the normal at that point (HitPoint), for everything shaded there. On the device the kinds'
// objectHitPoint are called (TRAZO_HD_DEVICE_CALL), all but the box's: inlined, they held the indirect-light
// kernels' registers across every hit (kernel_budget, scripts/kernel_resources.sh). On the host they and this are
// always inlined: called out of line by GCC's choice, they cost scene 6 a quarter of its time.
TRAZO_HD_HOT HitPoint hitPointOn(const SceneView& scene, const ObjectRef& o, const Ray& ray, SurfaceHit& hit) {
    const ShapeHit shapeHit = shapeHitOf(hit);
    const HitPoint at =
        visitObject(scene, o, [&](const auto& shape) { return objectHitPoint(scene, shape, ray, shapeHit); });
    hit.normal = at.normal;
    return at;
}

// m's colours times its textures at the surface's uv, and the normal map applied to s.n. Without uvs
// the textures are ignored (flatten() warns about such objects).
TRAZO_HD void applyTextures(const SceneView& scene, MaterialData& m, SurfacePoint& s) {
    if (!s.hasUv) return;
    const Vec3* texels = scene.texels.data;
    const int32_t kd = m.textures[kDiffuseTexture], ks = m.textures[kSpecularTexture];
    const int32_t ke = m.textures[kEmissiveTexture], normalMap = m.textures[kNormalTexture];
    if (kd >= 0) m.diffuse *= sampleTexture(scene.textures[kd], texels, s.u, s.v);
    if (ks >= 0) m.specular *= sampleTexture(scene.textures[ks], texels, s.u, s.v);
    if (ke >= 0) m.emissive *= sampleTexture(scene.textures[ke], texels, s.u, s.v);
    if (normalMap >= 0) {
        // The tangent frame made orthonormal about the shading normal, keeping its handedness.
        const Vec3 tRaw = s.tangent - s.n * dot(s.n, s.tangent);
        const Vec3 t = dot(tRaw, tRaw) > 1e-12f ? normalize(tRaw) : anyOrthonormal(s.n);
        const Vec3 b = dot(cross(s.n, t), s.bitangent) < 0.0f ? -cross(s.n, t) : cross(s.n, t);
        s.n = perturbNormal(s.n, t, b, sampleTexture(scene.textures[normalMap], texels, s.u, s.v));
    }
}

// The shading point at p for a ray along d, with both normals turned to face the ray (opaque insides,
// open surfaces).
TRAZO_HD_HOT ShadingPoint facingShadingPoint(Vec3 p, float offset, Vec3 d, const SurfacePoint& s) {
    const bool front = dot(d, s.ng) < 0.0f;
    return ShadingPoint{p, offset, front ? s.ng : -s.ng, front ? s.n : -s.n, -d};
}
TRAZO_HD ShadingPoint facingShadingPoint(Vec3 p, Vec3 pError, Vec3 d, const SurfacePoint& s) {
    return facingShadingPoint(p, offsetDistance(pError, s.ng), d, s);
}

// The shading point at Q, an object's `hit` along `ray`, and in mq its material with textures applied: Q where the
// object kind puts it (hitPointOn), for a ray from anywhere (the camera's).
TRAZO_HD ShadingPoint shadingPointAt(const SceneView& scene, const Ray& ray, SurfaceHit hit, MaterialData& mq) {
    const ObjectRef& o = scene.objects[hit.object];
    mq = scene.materials[o.material];
    const HitPoint q = hitPointOn(scene, o, ray, hit);
    SurfacePoint sq = surfaceAt(scene, o, hit, q.p, materialHasTextures(mq));
    applyTextures(scene, mq, sq);
    return facingShadingPoint(q.p, q.offset, ray.direction, sq);
}

// shadingPointAt for a ray that left a point of the scene (an indirect direction): Q = o + t·d, whose bound is then
// already at the scene's own scale, as the kind's would be. Cheaper on the device, where the kind's computation
// at every indirect hit put the indirect-light kernels over their spill budget (kernel_budget).
TRAZO_HD ShadingPoint shadingPointAlong(const SceneView& scene, const Ray& ray, const SurfaceHit& hit,
                                        MaterialData& mq) {
    const ObjectRef& o = scene.objects[hit.object];
    mq = scene.materials[o.material];
    SurfacePoint sq = surfaceAt(scene, o, hit, pointAt(ray, hit.t), materialHasTextures(mq));
    applyTextures(scene, mq, sq);
    return facingShadingPoint(pointAt(ray, hit.t), hitPointError(ray, hit.t), ray.direction, sq);
}

}  // namespace trazo
