// The triangle mesh object kind (host and device): world-space triangles in the order of the mesh's own BVH
// (SceneView::triangles, MeshTriangle), shading data per corner beside them (kept apart so traversal touches
// positions only), one MeshShape per Mesh block; its ray queries, surface and bounds (the host block:
// scene/kinds/mesh.h; flatten/flatten_mesh.h builds the arrays).
#pragma once

#include <cstdint>

#include "accel/bvh_traverse.h"
#include "accel/wide8_traverse.h"
#include "accel/wide_bvh_node.h"
#include "core/aabb.h"
#include "core/ray.h"
#include "core/vec3.h"
#include "geometry/intersect_triangle_leaf.h"
#include "geometry/surface_frame.h"
#include "objects/scene_view.h"

namespace trazo {

static_assert(kBvhMaxLeafSize <= kMaxLeafTriangles, "a mesh leaf must fit intersectTriangleLeaf");

// One corner's shading data: unit normal, Lengyel tangent with the bitangent's handedness (bitangent =
// tangentSign · normal × tangent), and texture coordinates.
struct MeshCorner {
    Vec3 normal;
    Vec3 tangent;
    float tangentSign;
    float u, v;
};

struct TriangleCorners {
    MeshCorner corner[3];
};

struct MeshShape {
    uint32_t nodeOffset;      // root of the mesh's BVH in SceneView::meshNodes
    uint32_t triangleOffset;  // first triangle in SceneView::triangles / triangleCorners
    uint32_t triangleCount;
    uint32_t hasUvs;          // 0: the OBJ had no uvs; textures are ignored on it
    uint32_t nodeOffset8 = 0;  // root of its eight-wide BVH in SceneView::meshNodes8, where there is one
    uint32_t anyHit8 = 0;      // 1: shadow rays take the eight-wide BVH too (a large mesh: widenMeshBvhs)
};

// Nearest triangle of the mesh in (tMin, tMax), of triangles at the same t the first in the mesh's order, so
// the answer does not depend on the order the BVH's leaves are visited in (four- or eight-wide nodes). The
// normal follows the triangle's winding (p0, p1, p2).
// `stack`: the traversal stack the mesh continues on (the top level's, in intersectScene).
TRAZO_HD bool intersectMesh(const SceneView& scene, const MeshShape& mesh, const Ray& ray, float tMin, float tMax,
                            ClosestStack& stack, ShapeHit& hit) {
    const TriangleRay tr = makeTriangleRay(ray);
    const MeshTriangle* triangles = scene.triangles.data + mesh.triangleOffset;
    uint32_t best = 0;
    TriangleHit bestHit{};
    Vec3 p0, p1, p2;  // the best triangle's vertices
    // Leaves hold disjoint ranges of triangles, so a leaf starting before the best hit's triangle lies wholly
    // before it: there a triangle at the same t wins too (tested up to the next float). Within a leaf the first
    // of equal ones wins already.
    auto leafLimit = [&](uint32_t first, float tNearest) { return first < best ? nextFloatUp(tNearest) : tNearest; };
#if TRAZO_HOST_AVX
    if (scene.meshNodes8.count > 0) {
        // Inlined: in the large tile units GCC would call it out of line from the traversal.
        const TriangleBlock* bestBlock = nullptr;
        auto blockLeaf = [&](uint32_t firstBlock, uint32_t blocks, float& tNearest) __attribute__((always_inline)) {
            const TriangleBlock* b = scene.triangleBlocks.data + firstBlock;
            uint32_t which = 0;
            auto found = [&](const TriangleBlock* run) {  // bestHit is now the run's hit `which`
                tNearest = bestHit.t;
                best = run->first + which;
                bestBlock = run + which / 4;  // a run's blocks but its last are full
                return true;
            };
#if TRAZO_HOST_AVX512
            if (blocks > 2)
                return intersectBlockQuad(tr, triangle_detail::BlockQuad{b, blocks == 4}, triangles, tMin,
                                          leafLimit(b->first, tNearest), bestHit, which) &&
                       found(b);
#endif
            bool hit = false;
            for (int left = (int)blocks; left > 0; left -= 2, b += 2)
                if (intersectBlockRun(tr, BlockRun{b, left > 1}, triangles, tMin, leafLimit(b->first, tNearest),
                                      bestHit, which))
                    hit = found(b);
            return hit;
        };
        if (!traverseClosest8(scene.meshNodes8.data + mesh.nodeOffset8, ray, tMin, tMax, stack, blockLeaf))
            return false;
        // The vertices from the block the leaf test read, not from the triangles: on a large mesh a cache miss less.
        const uint32_t lane = best - bestBlock->first;
        p0 = blockVertex(*bestBlock, 0, lane), p1 = blockVertex(*bestBlock, 1, lane), p2 = blockVertex(*bestBlock, 2, lane);
    } else
#endif
    {
        auto leaf = [&](uint32_t first, uint32_t count, float& tNearest) {
            uint32_t which = 0;
            if (!intersectTriangleLeaf(tr, triangles + first, count, tMin, leafLimit(first, tNearest), bestHit, which))
                return false;
            tNearest = bestHit.t;
            best = first + which;
            return true;
        };
        if (!traverseClosest(scene.meshNodes.data + mesh.nodeOffset, ray, tMin, tMax, stack, leaf)) return false;
        p0 = triangles[best].p0, p1 = triangles[best].p1, p2 = triangles[best].p2;
    }
    hit.t = bestHit.t;
    hit.normal = normalize(cross(p1 - p0, p2 - p0));
    hit.triangle = mesh.triangleOffset + best;
    hit.b1 = bestHit.b1;
    hit.b2 = bestHit.b2;
    return true;
}

// Whether some triangle of the mesh lies within (0, tMax): over its eight-wide BVH where it has one and
// anyHit8 (a large mesh), else over the four-wide one.
TRAZO_HD_HOST_CALL bool meshBlocks(const SceneView& scene, const MeshShape& mesh, const Ray& ray, float tMax, AnyStack& stack) {
    const TriangleRay tr = makeTriangleRay(ray);
    const MeshTriangle* triangles = scene.triangles.data + mesh.triangleOffset;
#if TRAZO_HOST_AVX
    if (mesh.anyHit8 && scene.meshNodes8.count > 0) {
        auto blockLeaf = [&](uint32_t firstBlock, uint32_t blocks, float tLimit) __attribute__((always_inline)) {
            const TriangleBlock* b = scene.triangleBlocks.data + firstBlock;
            for (int left = (int)blocks; left > 0; left -= 2, b += 2)
                if (blockRunBlocks(tr, BlockRun{b, left > 1}, triangles, 0.0f, tLimit)) return true;
            return false;
        };
        return traverseAny8(scene.meshNodes8.data + mesh.nodeOffset8, ray, 0.0f, tMax, blockLeaf);
    }
#endif
    auto leaf = [&](uint32_t first, uint32_t count, float tLimit) {
        return triangleLeafBlocks(tr, triangles + first, count, 0.0f, tLimit);
    };
    return traverseAny(scene.meshNodes.data + mesh.nodeOffset, ray, 0.0f, tMax, stack, leaf);
}

// Normal, uv and tangent interpolated from the corners. The geometric normal is turned to the side of the
// shading normal, so the file's normals (not its winding) say which side is outside.
TRAZO_HD SurfacePoint meshSurfaceAt(const SceneView& scene, const MeshShape& mesh, const ShapeHit& hit, bool wantUv) {
    const MeshCorner* c = scene.triangleCorners[hit.triangle].corner;
    const float b0 = 1.0f - hit.b1 - hit.b2;
    SurfacePoint s = plainSurface(hit);
    const Vec3 n = c[0].normal * b0 + c[1].normal * hit.b1 + c[2].normal * hit.b2;
    if (dot(n, n) > 0.0f) s.n = normalize(n);
    if (dot(s.n, s.ng) < 0.0f) s.ng = -s.ng;
    if (wantUv && mesh.hasUvs) {
        s.hasUv = true;
        s.u = c[0].u * b0 + c[1].u * hit.b1 + c[2].u * hit.b2;
        s.v = c[0].v * b0 + c[1].v * hit.b1 + c[2].v * hit.b2;
        s.tangent = c[0].tangent * b0 + c[1].tangent * hit.b1 + c[2].tangent * hit.b2;
        s.bitangent = cross(s.n, s.tangent) * c[0].tangentSign;
    }
    return s;
}

// The object kind's interface (objects/visit_object.h dispatches to it).
TRAZO_HD bool intersectObject(const SceneView& scene, const MeshShape& mesh, const Ray& ray, float tMax,
                              ClosestStack& stack, ShapeHit& hit) {
    return intersectMesh(scene, mesh, ray, 0.0f, tMax, stack, hit);
}

TRAZO_HD bool objectBlocks(const SceneView& scene, const MeshShape& mesh, const Ray& ray, float tMax,
                           AnyStack& stack) {
    return meshBlocks(scene, mesh, ray, tMax, stack);
}

TRAZO_HD SurfacePoint objectSurface(const SceneView& scene, const MeshShape& mesh, const ShapeHit& hit, Vec3,
                                    bool wantUv) {
    return meshSurfaceAt(scene, mesh, hit, wantUv);
}

TRAZO_HD bool objectHasUvs(const SceneView&, const MeshShape& mesh) { return mesh.hasUvs != 0; }

// The barycentric combination of the triangle's corners, wherever the ray came from. Its bound is a few ulps of
// the corners' largest coordinate in every axis, not pbrt-v4's per-axis one: a ray leaving the point is tested
// against the triangle in a frame sheared along that ray (intersect_triangle.h), which mixes the axes, so a point
// exactly on a plane z = 0 with corners at 1e5 must still leave it by ulps of 1e5.
TRAZO_HD_DEVICE_CALL HitPoint objectHitPoint(const SceneView& scene, const MeshShape&, const Ray& ray, const ShapeHit& hit) {
    const MeshTriangle& tri = scene.triangles[hit.triangle];
    const float b0 = 1.0f - hit.b1 - hit.b2;
    const Vec3 p = tri.p0 * b0 + tri.p1 * hit.b1 + tri.p2 * hit.b2;
    const float scale = maxComponent(abs(tri.p0) + abs(tri.p1) + abs(tri.p2));
    const HitPoint corners = boundedHitPoint(p, Vec3(scale * roundoff(8.0f)), hit.normal);
    return tighter(rayHitPoint(ray, hit.t, hit.normal), corners);
}

inline Aabb objectBounds(const SceneView& scene, const MeshShape& mesh) {
    return wideNodeBounds(scene.meshNodes[mesh.nodeOffset]);
}

}  // namespace trazo
