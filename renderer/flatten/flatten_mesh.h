// Meshes for the device scene: the OBJ data of one Mesh block in world space, with normals (given ones by
// the inverse transpose, missing ones computed) and Lengyel tangents, then its BVH appended to the arrays.
#pragma once

#include <vector>

#include "core/affine.h"
#include "flatten/scene_arrays.h"
#include "scene/scene.h"

namespace trazo {

struct PreparedMesh {
    std::vector<MeshTriangle> triangles;  // world space, in file order
    std::vector<TriangleCorners> corners;
    bool hasUvs = false;
};

// Positions go through worldFromObject; given normals through its inverse transpose. A corner without a
// normal gets the angle-weighted mean of the face normals around its position (smooth shading; OBJ
// smoothing groups are not read). Tangents: Lengyel's per-triangle dp/du, summed over the triangles that
// share a corner's (position, normal, uv), made orthogonal to the normal; with no usable uvs, any unit
// vector orthogonal to the normal.
PreparedMesh prepareMesh(const MeshData& data, const Affine3& worldFromObject);

// Builds the mesh's BVH and appends its nodes, triangles (in BVH order) and a MeshShape; returns the
// MeshShape's index in out.meshes.
uint32_t appendMesh(const PreparedMesh& mesh, SceneArrays& out);

// prepareMesh then appendMesh in one step, with the same result, without the PreparedMesh: each
// triangle's world positions and corners are written once, straight into their place in BVH order (for
// a large mesh, a third less memory at the peak and one copy fewer).
uint32_t appendMesh(const MeshData& data, const Affine3& worldFromObject, SceneArrays& out);

// The BVH nodes of MeshShape `shape`: meshes' nodes lie in meshNodes one mesh after another.
size_t meshNodeCount(const SceneArrays& arrays, uint32_t shape);

// Every mesh's eight-wide BVH (widenBvh), one after another, for SceneView::meshNodes8, and their leaves'
// triangles transposed (SceneView::triangleBlocks): each leaf reference of these nodes names bvhLeafCount
// consecutive blocks from bvhLeafFirst, not triangles. A leaf lane is one four-wide leaf or the leaves of a small
// subtree left over when a node's lanes are full (`groupLeaves`, widenBvh); its triangles are consecutive and fill
// its blocks four at a time, all full but the last. Sets each MeshShape's nodeOffset8, and its anyHit8 where it
// has at least `anyHit8Triangles` triangles. Where the CPU backend's AVX2 or AVX-512 kernels run
// (backends/cpu/cpu_backend.cpp). `out` is refilled in the memory it holds: fresh memory costs its page faults
// (50 MB of blocks for a million triangles: ~0.2 s on a VM, build/bench/bvh/bvh_bench), so an edit that moves a
// mesh reuses the last upload's.
struct EightWideMeshes {
    std::vector<WideBvhNode8> nodes;
    std::vector<TriangleBlock> blocks;
};
// Runs of up to four leaves, against runs of one (fewer 256-byte nodes fetched; bvh_bench, one thread, best of 2–3
// interleaved): a million triangles primary +8 %, shadow +7 %, random +10 %; the bunny primary +5 %, random +4 %.
constexpr uint32_t kMeshLeafGroup = 4;
// Meshes of at least this many triangles take their eight-wide BVH for shadow rays too (MeshShape::anyHit8):
// once the four-wide tree and its triangles outgrow the caches, fewer and denser nodes pay. Shadow rays over
// eight-wide against four-wide, bvh_bench's rays (AVX-512, one thread, best of 8): bunny 0.79×; bumpy spheres of
// 29k triangles 0.95×, 64k 1.00×, 131k 1.14×, 319k 1.19×, 1M 1.27× (`bvh_bench --scene sphere --only shadow
// --sphere-rings N` prints both trees' figures for a mesh of 2·N·(N − 1) triangles).
constexpr uint32_t kMeshAnyHit8Triangles = 1u << 16;
void widenMeshBvhs(SceneArrays& arrays, EightWideMeshes& out, uint32_t groupLeaves = kMeshLeafGroup,
                   uint32_t anyHit8Triangles = kMeshAnyHit8Triangles);

// Points the view's host-only eight-wide arrays at `meshes` (both, or a leaf names a block that is not there).
inline void viewEightWide(SceneView& view, const EightWideMeshes& meshes) {
    view.meshNodes8 = viewOf(meshes.nodes);
    view.triangleBlocks = viewOf(meshes.blocks);
}

}  // namespace trazo
