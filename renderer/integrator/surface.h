// What shading needs at a hit, beyond the hit itself: the shading normal (interpolated on meshes, then
// normal-mapped), texture coordinates and tangent frame, and the material with its textures applied
// (SPEC §5: Kd, Ks, Ke are the material colours times their textures).
#pragma once

#include "geometry/surface_frame.h"
#include "integrator/direct_light.h"
#include "integrator/scene_intersect.h"

namespace trazo {

struct SurfacePoint {
    Vec3 ng;  // unit outward geometric normal
    Vec3 n;   // unit outward shading normal
    bool hasUv;
    float u, v;
    Vec3 tangent, bitangent;  // unit; along increasing u and v (only when hasUv)
};

// Mesh hits: normal, uv and tangent interpolated from the corners. The geometric normal is turned to the
// side of the shading normal, so the file's normals (not its winding) say which side is outside.
TRAZO_HD SurfacePoint meshSurfaceAt(const SceneView& scene, const ObjectRef& o, const SurfaceHit& hit, bool wantUv) {
    const MeshCorner* c = scene.triangleCorners[hit.triangle].corner;
    const float b0 = 1.0f - hit.b1 - hit.b2;
    SurfacePoint s{hit.normal, hit.normal, false, 0.0f, 0.0f, Vec3(0.0f), Vec3(0.0f)};
    const Vec3 n = c[0].normal * b0 + c[1].normal * hit.b1 + c[2].normal * hit.b2;
    if (dot(n, n) > 0.0f) s.n = normalize(n);
    if (dot(s.n, s.ng) < 0.0f) s.ng = -s.ng;
    if (wantUv && scene.meshes[o.index].hasUvs) {
        s.hasUv = true;
        s.u = c[0].u * b0 + c[1].u * hit.b1 + c[2].u * hit.b2;
        s.v = c[0].v * b0 + c[1].v * hit.b1 + c[2].v * hit.b2;
        s.tangent = c[0].tangent * b0 + c[1].tangent * hit.b1 + c[2].tangent * hit.b2;
        s.bitangent = cross(s.n, s.tangent) * c[0].tangentSign;
    }
    return s;
}

// Whether any of the material's textures needs texture coordinates.
TRAZO_HD bool materialHasTextures(const MaterialData& m) {
    return m.diffuseTexture >= 0 || m.specularTexture >= 0 || m.emissiveTexture >= 0 || m.normalTexture >= 0;
}

// wantUv: the material has textures (materialHasTextures); without, the uv and tangent frame (an atan2 and an
// acos on a sphere) are skipped: applyTextures would not read them.
TRAZO_HD SurfacePoint surfaceAt(const SceneView& scene, const ObjectRef& o, const SurfaceHit& hit, Vec3 p, bool wantUv) {
    if (o.kind == ObjectKind::Mesh) return meshSurfaceAt(scene, o, hit, wantUv);
    SurfacePoint s{hit.normal, hit.normal, false, 0.0f, 0.0f, Vec3(0.0f), Vec3(0.0f)};
    if (!wantUv) return s;
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

// The shading point at p for a ray along d, with both normals turned to face the ray (opaque insides,
// open surfaces).
TRAZO_HD ShadingPoint facingShadingPoint(Vec3 p, Vec3 pError, Vec3 d, const SurfacePoint& s) {
    const bool front = dot(d, s.ng) < 0.0f;
    return ShadingPoint{p, pError, front ? s.ng : -s.ng, front ? s.n : -s.n, -d};
}

}  // namespace trazo
