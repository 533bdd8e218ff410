// Mesh preparation: world-space positions, normals and Lengyel tangents per corner; BVH and upload order.
// What is shared between triangles (world positions, computed normals, tangent sums) is computed once, and
// each triangle's corners are then derived from it independently, straight into their place in BVH order:
// no per-mesh copy of the triangles or corners is ever held beside SceneArrays.
#include "flatten/flatten_mesh.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "accel/bvh_build.h"
#include "accel/collapse_bvh.h"
#include "core/thread_pool.h"
#include "scene/obj_reader.h"

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

bool sameCorner(const MeshData::Corner& a, const MeshData::Corner& b) {
    return a.position == b.position && a.normal == b.normal && a.uv == b.uv;
}

uint64_t hashCorner(const MeshData::Corner& k) {
    uint64_t h = (uint64_t)(uint32_t)k.position * 0x9E3779B97F4A7C15ull;
    h ^= ((uint64_t)(uint32_t)k.normal + 0x632BE59BD9B4E019ull) * 0xC2B2AE3D27D4EB4Full;
    h ^= ((uint64_t)(uint32_t)k.uv + 0x85EBCA77C2B2AE63ull) * 0x165667B19E3779F9ull;
    return h ^ (h >> 29);
}

// Numbers the distinct (position, normal, uv) corners: out[i] is corner i's number, in order of first
// appearance. An open-addressing table of corner indices (4 bytes a slot, kept at most half full) instead
// of a node-based map: a million-triangle mesh has three million corners.
std::vector<uint32_t> numberDistinctCorners(const MeshCorners& corners, uint32_t& distinct) {
    std::vector<uint32_t> number(corners.size());
    size_t capacity = 1024;
    while (capacity < corners.size() / 2) capacity *= 2;  // most meshes have about a sixth as many vertices
    std::vector<uint32_t> table(capacity, UINT32_MAX);   // a representative corner's index, or empty
    distinct = 0;
    auto insertRepresentative = [&](std::vector<uint32_t>& t, uint32_t corner) {
        const size_t mask = t.size() - 1;
        for (size_t slot = hashCorner(corners[corner]) & mask;; slot = (slot + 1) & mask) {
            if (t[slot] == UINT32_MAX) {
                t[slot] = corner;
                return;
            }
        }
    };
    for (uint32_t i = 0; i < (uint32_t)corners.size(); ++i) {
        const MeshData::Corner c = corners[i];
        const size_t mask = table.size() - 1;
        size_t slot = hashCorner(c) & mask;
        for (;; slot = (slot + 1) & mask) {
            const uint32_t rep = table[slot];
            if (rep == UINT32_MAX) break;
            if (sameCorner(corners[rep], c)) break;
        }
        if (table[slot] != UINT32_MAX) {
            number[i] = number[table[slot]];
            continue;
        }
        table[slot] = i;
        number[i] = distinct++;
        if ((size_t)distinct * 2 > table.size()) {
            std::vector<uint32_t> bigger(table.size() * 2, UINT32_MAX);
            for (uint32_t rep : table)
                if (rep != UINT32_MAX) insertRepresentative(bigger, rep);
            table.swap(bigger);
        }
    }
    return number;
}

// Runs fn(begin, end) over [0, n) in one contiguous chunk per thread of the shared pool (one thread below
// 16384 items, where starting the others costs more than it saves); fn must only write what its own indices own.
template <typename Fn>
void parallelChunks(size_t n, Fn&& fn) {
    ThreadPool& pool = sharedThreadPool();
    const unsigned threads = n >= 16384 ? pool.threadCount() : 1u;
    if (threads == 1) {
        fn(size_t(0), n);
        return;
    }
    pool.parallelFor(n, (n + threads - 1) / threads, fn);
}

// What the triangles of one mesh share, computed once: world positions, smooth normals per position (when
// the file has no normals), Lengyel tangent sums per distinct corner (when it has uvs). Then any
// triangle's world positions and shading corners, independently of the others.
// Relies on the MeshData contract of scene/obj_reader.h and on nothing else: every index in range, the
// normal index used exactly when hasNormals, the uv index exactly when hasUvs, corner and triangle numbers
// that fit a uint32_t (asserted in debug builds; the OBJ reader refuses a file that breaks it).
class MeshShading {
public:
    MeshShading(const MeshData& data, const Affine3& worldFromObject)
        : data_(data), objectFromWorld_(inverse(worldFromObject)), positions_(data.positions.size()) {
        assert(objMeshContractViolation(data).empty() && "MeshData breaks the contract of scene/obj_reader.h");
        for (size_t i = 0; i < positions_.size(); ++i) positions_[i] = worldFromObject.applyToPoint(data.positions[i]);
        const size_t triangleCount = data.corners.size() / 3;

        // Smooth normals per position for corners without one: face normals weighted by the corner's angle
        // (summed in triangle order, as every corner of a position is).
        // Each thread owns a range of positions and walks every triangle, adding only to its own: every
        // sum is taken in the same order whatever the thread count.
        if (!data.hasNormals) {
            computedNormals_.assign(positions_.size(), Vec3(0.0f));
            const size_t positionCount = positions_.size();
            auto accumulate = [&](size_t ownedBegin, size_t ownedEnd) {
                for (size_t t = 0; t < triangleCount; ++t) {
                    const size_t position[3] = {(size_t)data.corners.position(3 * t),
                                                (size_t)data.corners.position(3 * t + 1),
                                                (size_t)data.corners.position(3 * t + 2)};
                    const bool mine[3] = {position[0] - ownedBegin < ownedEnd - ownedBegin,
                                          position[1] - ownedBegin < ownedEnd - ownedBegin,
                                          position[2] - ownedBegin < ownedEnd - ownedBegin};
                    if (!mine[0] && !mine[1] && !mine[2]) continue;
                    const MeshTriangle tri = triangle(t);
                    const Vec3 face = normalizeOr(cross(tri.p1 - tri.p0, tri.p2 - tri.p0), Vec3(0.0f));
                    const Vec3 p[3] = {tri.p0, tri.p1, tri.p2};
                    for (int k = 0; k < 3; ++k)
                        if (mine[k])
                            computedNormals_[position[k]] += face * cornerAngle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
                }
            };
            if (triangleCount >= 65536) parallelChunks(positionCount, accumulate);  // every thread walks them all
            else accumulate(0, positionCount);
        }

        // Lengyel's tangents, summed over the triangles sharing a corner's (position, normal, uv). Without
        // uvs every sum is zero, which gives anyOrthonormal(n) and a + handedness: nothing to number.
        if (data.hasUvs) {
            uint32_t distinct = 0;
            cornerVertex_ = numberDistinctCorners(data.corners, distinct);
            tangentSum_.assign(distinct, Vec3(0.0f));
            bitangentSum_.assign(distinct, Vec3(0.0f));
            for (size_t t = 0; t < triangleCount; ++t) {
                const MeshTriangle tri = triangle(t);
                float u[3], v[3];
                for (int k = 0; k < 3; ++k) uvOf(data.corners[3 * t + k], u[k], v[k]);
                const Vec3 e1 = tri.p1 - tri.p0, e2 = tri.p2 - tri.p0;
                const float du1 = u[1] - u[0], dv1 = v[1] - v[0];
                const float du2 = u[2] - u[0], dv2 = v[2] - v[0];
                const float det = du1 * dv2 - du2 * dv1;
                if (!(std::fabs(det) > 0.0f)) continue;  // uvs collapsed on this triangle: no direction to give
                const float r = 1.0f / det;
                const Vec3 tangent = (e1 * dv2 - e2 * dv1) * r;
                const Vec3 bitangent = (e2 * du1 - e1 * du2) * r;
                if (!isFinite(tangent) || !isFinite(bitangent)) continue;
                for (int k = 0; k < 3; ++k) {
                    tangentSum_[cornerVertex_[3 * t + k]] += tangent;
                    bitangentSum_[cornerVertex_[3 * t + k]] += bitangent;
                }
            }
        }
    }

    MeshTriangle triangle(size_t t) const {
        const MeshCorners& c = data_.corners;
        return {positions_[(size_t)c.position(3 * t)], positions_[(size_t)c.position(3 * t + 1)],
                positions_[(size_t)c.position(3 * t + 2)]};
    }

    TriangleCorners corners(size_t t) const {
        TriangleCorners out;
        const MeshTriangle tri = triangle(t);
        const Vec3 face = normalizeOr(cross(tri.p1 - tri.p0, tri.p2 - tri.p0), Vec3(0.0f, 1.0f, 0.0f));
        for (int k = 0; k < 3; ++k) {
            const MeshData::Corner c = data_.corners[3 * t + k];
            MeshCorner& mc = out.corner[k];
            const Vec3 n0 = data_.hasNormals
                                ? objectFromWorld_.applyTransposeToVector(data_.normals[(size_t)c.normal])
                                : computedNormals_[(size_t)c.position];
            const Vec3 n = normalizeOr(n0, face);
            mc.normal = n;
            uvOf(c, mc.u, mc.v);
            // Gram–Schmidt against the normal; the handedness says which way the bitangent points.
            const Vec3 ts = data_.hasUvs ? tangentSum_[cornerVertex_[3 * t + k]] : Vec3(0.0f);
            const Vec3 bs = data_.hasUvs ? bitangentSum_[cornerVertex_[3 * t + k]] : Vec3(0.0f);
            mc.tangent = normalizeOr(ts - n * dot(n, ts), anyOrthonormal(n));
            mc.tangentSign = dot(cross(n, mc.tangent), bs) < 0.0f ? -1.0f : 1.0f;
        }
        return out;
    }

    // The triangle's bounds as the BVH sees them.
    Aabb bounds(size_t t) const {
        const MeshTriangle tri = triangle(t);
        return Aabb{min(tri.p0, min(tri.p1, tri.p2)), max(tri.p0, max(tri.p1, tri.p2))};
    }

private:
    void uvOf(const MeshData::Corner& c, float& u, float& v) const {
        u = data_.hasUvs ? data_.uvs[2 * (size_t)c.uv] : 0.0f;
        v = data_.hasUvs ? data_.uvs[2 * (size_t)c.uv + 1] : 0.0f;
    }

    const MeshData& data_;
    const Affine3 objectFromWorld_;
    std::vector<Vec3> positions_;        // world space
    std::vector<Vec3> computedNormals_;  // per position, unnormalised; only without normals in the file
    std::vector<uint32_t> cornerVertex_;  // per corner: its distinct (position, normal, uv); only with uvs
    std::vector<Vec3> tangentSum_, bitangentSum_;
};

// Appends the wide nodes of `bvh` (moved when they are the first) and the MeshShape of a mesh whose
// triangles will be placed at out.triangles[first ...]; returns the shape's index.
uint32_t appendShape(const Bvh& bvh, uint32_t first, uint32_t count, bool hasUvs, SceneArrays& out) {
    std::vector<WideBvhNode> nodes = collapseBvh(bvh);
    const MeshShape shape{(uint32_t)out.meshNodes.size(), first, count, hasUvs ? 1u : 0u};
    if (out.meshNodes.empty()) out.meshNodes = std::move(nodes);
    else out.meshNodes.insert(out.meshNodes.end(), nodes.begin(), nodes.end());
    out.meshes.push_back(shape);
    return (uint32_t)out.meshes.size() - 1;
}

// Hands the pages of freed heap blocks back to the system after the temporaries of a mesh, or meshes, of
// `triangles` triangles were freed. glibc raises its mmap threshold as large blocks are freed (up to 32 MB),
// so a large mesh's temporaries (the BVH builder's, the shading's, widenBvh's) end up in the heap, where
// free() keeps their pages resident; what is allocated next would be counted on top. Below
// kReleaseHeapTriangles they are too small to matter, and malloc_trim walks every free chunk of the heap
// (0.2 ms on a fragmented one), which a scene of many small meshes would pay for each.
constexpr size_t kReleaseHeapTriangles = size_t(1) << 16;
void releaseFreedHeap(size_t triangles) {
#if defined(__GLIBC__)
    if (triangles >= kReleaseHeapTriangles) malloc_trim(0);
#else
    (void)triangles;
#endif
}

// Builds the BVH of `count` triangles (bounds(t): triangle t's box), appends its nodes and MeshShape, then
// writes the triangles in its leaf order on all cores: write(k, t) puts triangle t at out.triangles[k] and
// out.triangleCorners[k]. Returns the MeshShape's index.
template <class BoundsFn, class WriteFn>
uint32_t appendInBvhOrder(uint32_t count, bool hasUvs, SceneArrays& out, BoundsFn&& bounds, WriteFn&& write) {
    const size_t first = out.triangles.size();
    std::vector<uint32_t> order;
    uint32_t index;
    {  // the binary BVH and the builder's arrays are gone before the triangles are written
        Bvh bvh = buildBvh(count, bounds, triangleBvhOptions());
        // collapseBvh reserves about twice the nodes it makes, where the builder's temporaries lay: their pages
        // go back first, or that spare capacity would keep them resident as long as the scene's arrays (6 MB for
        // a million triangles, at the peak).
        releaseFreedHeap(count);
        index = appendShape(bvh, (uint32_t)first, count, hasUvs, out);
        order = std::move(bvh.primitiveOrder);
    }
    releaseFreedHeap(count);
    out.triangles.resize(first + count);
    out.triangleCorners.resize(first + count);
    parallelChunks(count, [&](size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) write(first + i, order[i]);
    });
    return index;
}

}  // namespace

PreparedMesh prepareMesh(const MeshData& data, const Affine3& worldFromObject) {
    PreparedMesh out;
    const size_t triangleCount = data.corners.size() / 3;
    out.hasUvs = data.hasUvs;
    out.triangles.resize(triangleCount);
    out.corners.resize(triangleCount);
    const MeshShading shading(data, worldFromObject);
    parallelChunks(triangleCount, [&](size_t b, size_t e) {
        for (size_t t = b; t < e; ++t) {
            out.triangles[t] = shading.triangle(t);
            out.corners[t] = shading.corners(t);
        }
    });
    return out;
}

uint32_t appendMesh(const PreparedMesh& mesh, SceneArrays& out) {
    return appendInBvhOrder(
        (uint32_t)mesh.triangles.size(), mesh.hasUvs, out,
        [&](uint32_t t) {
            const MeshTriangle& tri = mesh.triangles[t];
            return Aabb{min(tri.p0, min(tri.p1, tri.p2)), max(tri.p0, max(tri.p1, tri.p2))};
        },
        [&](size_t k, uint32_t t) {
            out.triangles[k] = mesh.triangles[t];
            out.triangleCorners[k] = mesh.corners[t];
        });
}

uint32_t appendMesh(const MeshData& data, const Affine3& worldFromObject, SceneArrays& out) {
    uint32_t index;
    {
        const MeshShading shading(data, worldFromObject);
        index = appendInBvhOrder(
            (uint32_t)(data.corners.size() / 3), data.hasUvs, out, [&](uint32_t t) { return shading.bounds(t); },
            [&](size_t k, uint32_t t) {
                out.triangles[k] = shading.triangle(t);
                out.triangleCorners[k] = shading.corners(t);
            });
    }
    // The shading's world positions and normals and the BVH order (16 MB for a million triangles) were freed
    // into the heap: without this their pages stay resident through the upload, the process's peak.
    releaseFreedHeap(data.corners.size() / 3);
    return index;
}

size_t meshNodeCount(const SceneArrays& arrays, uint32_t shape) {
    const size_t end = shape + 1 < arrays.meshes.size() ? arrays.meshes[shape + 1].nodeOffset : arrays.meshNodes.size();
    return end - arrays.meshes[shape].nodeOffset;
}

namespace {

// triangles[first, first + count) (count ≤ 4) transposed; lanes past count repeat the first triangle.
TriangleBlock transposeTriangles(const MeshTriangle* triangles, uint32_t first, uint32_t count) {
    TriangleBlock block;
    for (uint32_t lane = 0; lane < 4; ++lane) {
        const MeshTriangle& t = triangles[first + (lane < count ? lane : 0)];
        const Vec3 vertex[3] = {t.p0, t.p1, t.p2};
        for (int k = 0; k < 3; ++k)
            for (int axis = 0; axis < 3; ++axis) block.v[k][axis][lane] = vertex[k][axis];
    }
    block.first = first;
    block.count = count;
    block.padding[0] = block.padding[1] = 0;
    return block;
}

// A leaf lane of widenBvh's, naming the run runLeaves[bvhLeafFirst(ref), +bvhLeafCount(ref)) of four-wide
// leaves, as blocks: the run's triangles are consecutive (a subtree's, in BVH order), so they fill blocks four
// at a time however the leaves split them (bvh_bench, over trees widened greedily: a ray tests 5.18 blocks on the
// bunny where one block a leaf took 5.63, 5.39 where 5.61 on a million triangles). Returns the lane's reference to
// its blocks.
uint32_t appendRunBlocks(uint32_t ref, const std::vector<uint32_t>& runLeaves, const MeshTriangle* triangles,
                         std::vector<TriangleBlock>& blocks) {
    const uint32_t* run = runLeaves.data() + bvhLeafFirst(ref);
    const uint32_t first = bvhLeafFirst(run[0]);
    uint32_t count = 0;
    for (uint32_t l = 0; l < bvhLeafCount(ref); ++l) {
        assert(bvhLeafFirst(run[l]) == first + count);
        count += bvhLeafCount(run[l]);
    }
    const uint32_t firstBlock = (uint32_t)blocks.size();
    for (uint32_t done = 0; done < count; done += 4)
        blocks.push_back(transposeTriangles(triangles, first + done, std::min(4u, count - done)));
    return bvhLeafRef(firstBlock, (uint32_t)blocks.size() - firstBlock);  // ⌈count / 4⌉ ≤ the run's length
}

}  // namespace

void widenMeshBvhs(SceneArrays& arrays, EightWideMeshes& out, uint32_t groupLeaves, uint32_t anyHit8Triangles) {
    static_assert(kBvhMaxLeafSize == 4, "a leaf's triangles fit one four-lane block");
    out.nodes.clear();
    out.blocks.clear();
    if (arrays.meshes.empty()) return;
    size_t leaves = 0;  // the four-wide trees' leaves: at least as many as the blocks they pack into
    for (const WideBvhNode& node : arrays.meshNodes)
        for (uint32_t ref : node.child) leaves += ref != kBvhEmptyLane && bvhIsLeaf(ref);
    out.blocks.reserve(leaves);
    out.nodes.reserve(arrays.meshNodes.size());  // an eight-wide tree has fewer nodes than its four-wide one
    // Every mesh's tree first, their leaf runs in one list (each four-wide leaf is in one run)...
    std::vector<uint32_t> runLeaves;
    runLeaves.reserve(leaves);
    for (uint32_t i = 0; i < arrays.meshes.size(); ++i) {
        MeshShape& shape = arrays.meshes[i];
        shape.nodeOffset8 = (uint32_t)out.nodes.size();
        shape.anyHit8 = shape.triangleCount >= anyHit8Triangles;
        widenBvh(arrays.meshNodes.data() + shape.nodeOffset, meshNodeCount(arrays, i), out.nodes, &runLeaves,
                 groupLeaves);
    }
    // ...then the blocks, the largest array, once widenBvh's temporaries (16 MB for a million triangles, freed
    // into the heap) have handed their pages back: on top of the scene's arrays they made the process's peak.
    releaseFreedHeap(arrays.triangles.size());
    for (uint32_t i = 0; i < arrays.meshes.size(); ++i) {
        const MeshShape& shape = arrays.meshes[i];
        const size_t end = i + 1 < arrays.meshes.size() ? arrays.meshes[i + 1].nodeOffset8 : out.nodes.size();
        const MeshTriangle* triangles = arrays.triangles.data() + shape.triangleOffset;
        // Blocks in the order of the nodes that name them: a node's runs lie side by side.
        for (size_t n = shape.nodeOffset8; n < end; ++n)
            for (uint32_t& ref : out.nodes[n].child)
                if (ref != kBvhEmptyLane && bvhIsLeaf(ref))
                    ref = appendRunBlocks(ref, runLeaves, triangles, out.blocks);
    }
}

}  // namespace trazo
