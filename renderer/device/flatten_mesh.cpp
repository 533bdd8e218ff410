// Mesh preparation: world-space positions, normals and Lengyel tangents per corner; BVH and upload order.
#include "device/flatten_mesh.h"

#include <cmath>
#include <unordered_map>

#include "accel/bvh_build.h"
#include "accel/collapse_bvh.h"

namespace trazo {

namespace {

Vec3 normalizeOr(Vec3 v, Vec3 fallback) {
    const float len2 = dot(v, v);
    return len2 > 0.0f && std::isfinite(len2) ? v / std::sqrt(len2) : fallback;
}

// The interior angle at corner a of triangle (a, b, c); 0 for a degenerate corner.
float cornerAngle(Vec3 a, Vec3 b, Vec3 c) {
    const Vec3 e1 = b - a, e2 = c - a;
    const float l = std::sqrt(dot(e1, e1) * dot(e2, e2));
    return l > 0.0f ? std::acos(std::fmin(1.0f, std::fmax(-1.0f, dot(e1, e2) / l))) : 0.0f;
}

struct CornerKey {
    int32_t position, normal, uv;
    bool operator==(const CornerKey& o) const { return position == o.position && normal == o.normal && uv == o.uv; }
};
struct CornerKeyHash {
    size_t operator()(const CornerKey& k) const {
        uint64_t h = (uint64_t)(uint32_t)k.position * 0x9E3779B97F4A7C15ull;
        h ^= ((uint64_t)(uint32_t)k.normal + 0x632BE59BD9B4E019ull) * 0xC2B2AE3D27D4EB4Full;
        h ^= ((uint64_t)(uint32_t)k.uv + 0x85EBCA77C2B2AE63ull) * 0x165667B19E3779F9ull;
        return size_t(h ^ (h >> 29));
    }
};

}  // namespace

PreparedMesh prepareMesh(const MeshData& data, const Affine3& worldFromObject) {
    PreparedMesh out;
    const size_t triangleCount = data.corners.size() / 3;
    out.hasUvs = data.hasUvs;
    out.triangles.resize(triangleCount);
    out.corners.resize(triangleCount);

    std::vector<Vec3> positions(data.positions.size());
    for (size_t i = 0; i < positions.size(); ++i) positions[i] = worldFromObject.applyToPoint(data.positions[i]);
    const Affine3 objectFromWorld = inverse(worldFromObject);

    for (size_t t = 0; t < triangleCount; ++t) {
        const MeshData::Corner* c = &data.corners[3 * t];
        out.triangles[t] = {positions[c[0].position], positions[c[1].position], positions[c[2].position]};
    }

    // Smooth normals per position for corners without one: face normals weighted by the corner's angle.
    std::vector<Vec3> computedNormals;
    if (!data.hasNormals) {
        computedNormals.assign(positions.size(), Vec3(0.0f));
        for (size_t t = 0; t < triangleCount; ++t) {
            const MeshTriangle& tri = out.triangles[t];
            const Vec3 face = normalizeOr(cross(tri.p1 - tri.p0, tri.p2 - tri.p0), Vec3(0.0f));
            const Vec3 p[3] = {tri.p0, tri.p1, tri.p2};
            for (int k = 0; k < 3; ++k)
                computedNormals[data.corners[3 * t + k].position] += face * cornerAngle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
        }
    }

    for (size_t t = 0; t < triangleCount; ++t) {
        const MeshTriangle& tri = out.triangles[t];
        const Vec3 face = normalizeOr(cross(tri.p1 - tri.p0, tri.p2 - tri.p0), Vec3(0.0f, 1.0f, 0.0f));
        for (int k = 0; k < 3; ++k) {
            const MeshData::Corner& c = data.corners[3 * t + k];
            MeshCorner& mc = out.corners[t].corner[k];
            const Vec3 n = c.normal >= 0 ? objectFromWorld.applyTransposeToVector(data.normals[c.normal])
                                         : computedNormals[c.position];
            mc.normal = normalizeOr(n, face);
            mc.u = c.uv >= 0 ? data.uvs[2 * c.uv] : 0.0f;
            mc.v = c.uv >= 0 ? data.uvs[2 * c.uv + 1] : 0.0f;
        }
    }

    // Lengyel's tangents, summed over the triangles sharing a corner's (position, normal, uv).
    std::unordered_map<CornerKey, uint32_t, CornerKeyHash> vertexOf;
    vertexOf.reserve(data.corners.size());
    std::vector<uint32_t> cornerVertex(data.corners.size());
    for (size_t i = 0; i < data.corners.size(); ++i) {
        const MeshData::Corner& c = data.corners[i];
        cornerVertex[i] = vertexOf.try_emplace(CornerKey{c.position, c.normal, c.uv}, (uint32_t)vertexOf.size()).first->second;
    }
    std::vector<Vec3> tangentSum(vertexOf.size(), Vec3(0.0f)), bitangentSum(vertexOf.size(), Vec3(0.0f));
    if (data.hasUvs) {
        for (size_t t = 0; t < triangleCount; ++t) {
            const MeshTriangle& tri = out.triangles[t];
            const MeshCorner* mc = out.corners[t].corner;
            const Vec3 e1 = tri.p1 - tri.p0, e2 = tri.p2 - tri.p0;
            const float du1 = mc[1].u - mc[0].u, dv1 = mc[1].v - mc[0].v;
            const float du2 = mc[2].u - mc[0].u, dv2 = mc[2].v - mc[0].v;
            const float det = du1 * dv2 - du2 * dv1;
            if (!(std::fabs(det) > 0.0f)) continue;  // uvs collapsed on this triangle: no direction to give
            const float r = 1.0f / det;
            const Vec3 tangent = (e1 * dv2 - e2 * dv1) * r;
            const Vec3 bitangent = (e2 * du1 - e1 * du2) * r;
            if (!isFinite(tangent) || !isFinite(bitangent)) continue;
            for (int k = 0; k < 3; ++k) {
                tangentSum[cornerVertex[3 * t + k]] += tangent;
                bitangentSum[cornerVertex[3 * t + k]] += bitangent;
            }
        }
    }
    for (size_t t = 0; t < triangleCount; ++t) {
        for (int k = 0; k < 3; ++k) {
            MeshCorner& mc = out.corners[t].corner[k];
            const uint32_t vtx = cornerVertex[3 * t + k];
            const Vec3 n = mc.normal;
            // Gram–Schmidt against the normal; the handedness says which way the bitangent points.
            mc.tangent = normalizeOr(tangentSum[vtx] - n * dot(n, tangentSum[vtx]), anyOrthonormal(n));
            mc.tangentSign = dot(cross(n, mc.tangent), bitangentSum[vtx]) < 0.0f ? -1.0f : 1.0f;
        }
    }
    return out;
}

uint32_t appendMesh(const PreparedMesh& mesh, SceneArrays& out) {
    std::vector<Aabb> bounds(mesh.triangles.size());
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        const MeshTriangle& t = mesh.triangles[i];
        bounds[i] = Aabb{min(t.p0, min(t.p1, t.p2)), max(t.p0, max(t.p1, t.p2))};
    }
    const Bvh bvh = buildBvh(bounds, triangleBvhOptions());
    const std::vector<WideBvhNode> nodes = collapseBvh(bvh);
    const MeshShape shape{(uint32_t)out.meshNodes.size(), (uint32_t)out.triangles.size(),
                          (uint32_t)mesh.triangles.size(), mesh.hasUvs ? 1u : 0u};
    out.meshNodes.insert(out.meshNodes.end(), nodes.begin(), nodes.end());
    for (uint32_t old : bvh.primitiveOrder) {
        out.triangles.push_back(mesh.triangles[old]);
        out.triangleCorners.push_back(mesh.corners[old]);
    }
    out.meshes.push_back(shape);
    return (uint32_t)out.meshes.size() - 1;
}

}  // namespace trazo
