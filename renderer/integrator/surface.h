// What shading needs at a hit, beyond the hit itself: the shading normal (interpolated on meshes, then
// normal-mapped), texture coordinates and tangent frame, and the material with its textures applied
// (SPEC §5: Kd, Ks, Ke are the material colours times their textures).
#pragma once

#include "geometry/surface_frame.h"
#include "integrator/scene_intersect.h"

namespace trazo {

struct SurfacePoint {
    Vec3 ng;  // unit outward geometric normal
    Vec3 n;   // unit outward shading normal
    bool hasUv;
    float u, v;
    Vec3 tangent, bitangent;  // unit; along increasing u and v (only when hasUv)
};

TRAZO_HD SurfacePoint surfaceAt(const SceneView& scene, const ObjectRef& o, const SurfaceHit& hit, Vec3 p) {
    SurfacePoint s{hit.normal, hit.normal, false, 0.0f, 0.0f, Vec3(0.0f), Vec3(0.0f)};
    SurfaceFrame f{};
    switch (o.kind) {
        case ObjectKind::Sphere: f = sphereFrame(scene.spheres[o.index], p); break;
        case ObjectKind::Box: f = boxFrame(scene.boxes[o.index], p); break;
        case ObjectKind::Cylinder: f = cylinderFrame(scene.cylinders[o.index], p, hit.normal); break;
        default: return s;  // CSG solids have no texture coordinates
    }
    s.hasUv = true;
    s.u = f.u;
    s.v = f.v;
    s.tangent = f.tangent;
    s.bitangent = f.bitangent;
    return s;
}

// m's colours times its textures at the surface's uv, and the normal map applied to s.n. Without uvs
// the textures are ignored (flatten() warns about such objects).
TRAZO_HD void applyTextures(const SceneView& scene, MaterialData& m, SurfacePoint& s) {
    if (!s.hasUv) return;
    const Vec3* texels = scene.texels.data;
    if (m.diffuseTexture >= 0) m.diffuse *= sampleTexture(scene.textures[m.diffuseTexture], texels, s.u, s.v);
    if (m.specularTexture >= 0) m.specular *= sampleTexture(scene.textures[m.specularTexture], texels, s.u, s.v);
    if (m.emissiveTexture >= 0) m.emissive *= sampleTexture(scene.textures[m.emissiveTexture], texels, s.u, s.v);
    if (m.normalTexture >= 0) {
        // The tangent frame made orthonormal about the shading normal, keeping its handedness.
        const Vec3 tRaw = s.tangent - s.n * dot(s.n, s.tangent);
        const Vec3 t = dot(tRaw, tRaw) > 1e-12f ? normalize(tRaw) : anyOrthonormal(s.n);
        const Vec3 b = dot(cross(s.n, t), s.bitangent) < 0.0f ? -cross(s.n, t) : cross(s.n, t);
        s.n = perturbNormal(s.n, t, b, sampleTexture(scene.textures[m.normalTexture], texels, s.u, s.v));
    }
}

}  // namespace trazo
