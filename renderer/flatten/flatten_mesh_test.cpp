// Mesh preparation: transforms (positions, normals by the inverse transpose), computed normals, Lengyel
// tangents and their handedness, and the BVH order of what appendMesh uploads.
#include "flatten/flatten_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <set>

#include "support/tessellate.h"

namespace trazo {
namespace {

// Triangle-list positions → MeshData with shared position indices (so computed normals can smooth).
MeshData indexedMesh(const std::vector<Vec3>& triangleList) {
    MeshData m;
    for (const Vec3& p : triangleList) {
        int32_t index = -1;
        for (size_t i = 0; i < m.positions.size() && index < 0; ++i)
            if (m.positions[i].x == p.x && m.positions[i].y == p.y && m.positions[i].z == p.z) index = (int32_t)i;
        if (index < 0) {
            index = (int32_t)m.positions.size();
            m.positions.push_back(p);
        }
        m.corners.push_back({index, -1, -1});
    }
    return m;
}

// A unit quad in the XY plane, two triangles, with uvs (optionally mirrored in u) and a +Z normal.
MeshData quad(bool mirrorU) {
    MeshData m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    const float u1 = mirrorU ? 0.0f : 1.0f, u0 = 1.0f - u1;
    m.uvs = {u0, 0, u1, 0, u1, 1, u0, 1};
    m.normals = {Vec3(0, 0, 1)};
    for (int32_t i : {0, 1, 2, 0, 2, 3}) m.corners.push_back({i, 0, i});
    m.hasNormals = m.hasUvs = true;
    return m;
}

TEST(PrepareMesh, ComputedNormalsOfASphereAreRadial) {
    const MeshData sphere = indexedMesh(tessellateSphere(Vec3(0), 1.0f, 24, 48));
    const PreparedMesh mesh = prepareMesh(sphere, Affine3{});
    float worst = 1.0f;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Vec3 p[3] = {mesh.triangles[t].p0, mesh.triangles[t].p1, mesh.triangles[t].p2};
        for (int k = 0; k < 3; ++k) worst = std::min(worst, dot(mesh.corners[t].corner[k].normal, normalize(p[k])));
    }
    EXPECT_GT(worst, 0.9995f);  // within 1.8° of the true normal everywhere, poles included
}

// Scaling by (2, 1, 1) then rotating: a normal (1, 1, 0)/√2 must become M⁻ᵀ n, not M n.
TEST(PrepareMesh, GivenNormalsGoThroughTheInverseTranspose) {
    MeshData m = quad(false);
    m.normals = {normalize(Vec3(1, 1, 0))};
    const Affine3 world = then(makeScale(Vec3(2, 1, 1)), makeRotation(Vec3(0, 0, 1), 0.5f));
    const PreparedMesh mesh = prepareMesh(m, world);
    const Vec3 expected = normalize(makeRotation(Vec3(0, 0, 1), 0.5f).applyToVector(Vec3(0.5f, 1, 0)));
    const Vec3 got = mesh.corners[0].corner[0].normal;
    EXPECT_NEAR(got.x, expected.x, 1e-5f);
    EXPECT_NEAR(got.y, expected.y, 1e-5f);
    EXPECT_NEAR(got.z, expected.z, 1e-5f);
    const Vec3 p2 = world.applyToPoint(Vec3(1, 1, 0));
    EXPECT_NEAR(mesh.triangles[0].p2.x, p2.x, 1e-6f);
    EXPECT_NEAR(mesh.triangles[0].p2.y, p2.y, 1e-6f);
}

TEST(PrepareMesh, LengyelTangentFollowsUAndHandednessFollowsMirroring) {
    for (bool mirror : {false, true}) {
        const Affine3 world = makeRotation(normalize(Vec3(1, 2, 3)), 0.8f);
        const PreparedMesh mesh = prepareMesh(quad(mirror), world);
        const Vec3 uDirection = world.applyToVector(Vec3(mirror ? -1.0f : 1.0f, 0, 0));
        const Vec3 vDirection = world.applyToVector(Vec3(0, 1, 0));
        for (const TriangleCorners& tc : mesh.corners)
            for (const MeshCorner& c : tc.corner) {
                EXPECT_GT(dot(c.tangent, uDirection), 0.9999f) << "mirror " << mirror;
                EXPECT_NEAR(dot(c.tangent, c.normal), 0.0f, 1e-6f);
                // bitangent = sign · n × t must point along increasing v.
                EXPECT_GT(dot(cross(c.normal, c.tangent) * c.tangentSign, vDirection), 0.9999f) << "mirror " << mirror;
            }
    }
}

TEST(PrepareMesh, DegenerateTrianglesAndMissingUvsStayFinite) {
    const MeshData m = indexedMesh(degenerateTriangles(40, 3));
    const PreparedMesh mesh = prepareMesh(m, Affine3{});
    for (const TriangleCorners& tc : mesh.corners)
        for (const MeshCorner& c : tc.corner) {
            EXPECT_TRUE(isFinite(c.normal) && isFinite(c.tangent));
            EXPECT_NEAR(length(c.normal), 1.0f, 1e-5f);
            EXPECT_NEAR(length(c.tangent), 1.0f, 1e-5f);
        }
}

TEST(AppendMesh, TrianglesGoInBvhLeafOrderAndEachLeafBoundsItsTriangles) {
    const MeshData m = indexedMesh(randomTriangleSoup(300, 5));
    SceneArrays arrays;
    const uint32_t first = appendMesh(prepareMesh(m, Affine3{}), arrays);
    const uint32_t second = appendMesh(prepareMesh(m, makeTranslation(Vec3(5, 0, 0))), arrays);
    ASSERT_EQ(arrays.meshes.size(), 2u);
    EXPECT_EQ(arrays.triangles.size(), 600u);
    for (uint32_t meshIndex : {first, second}) {
        const MeshShape& shape = arrays.meshes[meshIndex];
        EXPECT_EQ(shape.triangleCount, 300u);
        const WideBvhNode* nodes = arrays.meshNodes.data() + shape.nodeOffset;
        const size_t nodeCount = (meshIndex == first ? arrays.meshes[second].nodeOffset : arrays.meshNodes.size()) -
                                 shape.nodeOffset;
        uint32_t covered = 0;
        for (uint32_t n = 0; n < nodeCount; ++n)
            for (int lane = 0; lane < kBvhWidth; ++lane) {
                const uint32_t ref = nodes[n].child[lane];
                if (ref == kBvhEmptyLane || !bvhIsLeaf(ref)) continue;
                for (uint32_t i = bvhLeafFirst(ref); i < bvhLeafFirst(ref) + bvhLeafCount(ref); ++i) {
                    const MeshTriangle& t = arrays.triangles[shape.triangleOffset + i];
                    for (const Vec3 p : {t.p0, t.p1, t.p2})
                        for (int a = 0; a < 3; ++a) {
                            EXPECT_GE(p[a], nodes[n].bounds[a][0][lane]);
                            EXPECT_LE(p[a], nodes[n].bounds[a][1][lane]);
                        }
                    ++covered;
                }
            }
        EXPECT_EQ(covered, 300u);
    }
}

// widenMeshBvhs: each mesh's eight-wide leaves name blocks of their own, each holding consecutive triangles lane
// by lane (the rest repeating its first), a lane's blocks one after another and all full but the last, and
// together they cover every triangle once. A lane of runs of one is a four-wide leaf's block; longer runs pack
// the triangles of their leaves, so they take no more blocks than their leaves, and some fewer.
TEST(WidenMeshBvhs, EveryLeafNamesFullBlocksOfItsOwnTriangles) {
    SceneArrays arrays;
    const MeshData soup = indexedMesh(randomTriangleSoup(300, 5));
    appendMesh(prepareMesh(soup, Affine3{}), arrays);
    appendMesh(prepareMesh(indexedMesh(tessellateSphere(Vec3(0), 1.0f, 12, 24)), Affine3{}), arrays);
    appendMesh(prepareMesh(indexedMesh(randomTriangleSoup(3, 9)), makeTranslation(Vec3(5, 0, 0))), arrays);
    std::set<std::pair<uint32_t, uint32_t>> fourWideLeaves;  // (mesh, leaf reference)
    for (uint32_t m = 0; m < arrays.meshes.size(); ++m)
        for (size_t n = 0; n < meshNodeCount(arrays, m); ++n)
            for (uint32_t ref : arrays.meshNodes[arrays.meshes[m].nodeOffset + n].child)
                if (ref != kBvhEmptyLane && bvhIsLeaf(ref)) fourWideLeaves.insert({m, ref});
    size_t leafBlocks = 0;
    for (uint32_t group : {1u, 2u, 4u}) {
        EightWideMeshes wide;
        wide.blocks.resize(7);  // what a previous upload left is replaced
        widenMeshBvhs(arrays, wide, group);
        std::vector<int> blockUses(wide.blocks.size(), 0);
        for (uint32_t m = 0; m < arrays.meshes.size(); ++m) {
            const MeshShape& shape = arrays.meshes[m];
            const size_t end = m + 1 < arrays.meshes.size() ? arrays.meshes[m + 1].nodeOffset8 : wide.nodes.size();
            std::vector<int> triangleUses(shape.triangleCount, 0);
            for (size_t n = shape.nodeOffset8; n < end; ++n)
                for (int lane = 0; lane < kBvh8Width; ++lane) {
                    const uint32_t ref = wide.nodes[n].child[lane];
                    if (ref == kBvhEmptyLane || !bvhIsLeaf(ref)) continue;
                    ASSERT_LE(bvhLeafFirst(ref) + bvhLeafCount(ref), wide.blocks.size());
                    ASSERT_LE(bvhLeafCount(ref), group);
                    const TriangleBlock* blocks = wide.blocks.data() + bvhLeafFirst(ref);
                    if (group == 1) {
                        EXPECT_TRUE(fourWideLeaves.count({m, bvhLeafRef(blocks[0].first, blocks[0].count)}));
                    }
                    for (uint32_t b = 0; b < bvhLeafCount(ref); ++b) {
                        const TriangleBlock& block = blocks[b];
                        ++blockUses[bvhLeafFirst(ref) + b];
                        const uint32_t count = block.count;
                        ASSERT_GE(count, 1u);
                        ASSERT_LE(block.first + count, shape.triangleCount);
                        if (b + 1 < bvhLeafCount(ref)) {
                            EXPECT_EQ(count, 4u);
                            EXPECT_EQ(blocks[b + 1].first, block.first + 4);
                        }
                        for (uint32_t k = 0; k < 4; ++k) {
                            const MeshTriangle& t =
                                arrays.triangles[shape.triangleOffset + block.first + (k < count ? k : 0)];
                            const Vec3 vertex[3] = {t.p0, t.p1, t.p2};
                            for (int v = 0; v < 3; ++v)
                                for (int a = 0; a < 3; ++a) EXPECT_EQ(block.v[v][a][k], vertex[v][a]);
                            if (k < count) ++triangleUses[block.first + k];
                        }
                    }
                }
            for (uint32_t i = 0; i < shape.triangleCount; ++i)
                EXPECT_EQ(triangleUses[i], 1) << "mesh " << m << ", triangle " << i << ", runs of " << group;
        }
        for (size_t b = 0; b < blockUses.size(); ++b) EXPECT_EQ(blockUses[b], 1) << "block " << b;
        if (group == 1) {
            EXPECT_EQ(wide.blocks.size(), fourWideLeaves.size());
            leafBlocks = wide.blocks.size();
        } else {
            EXPECT_LE(wide.blocks.size(), leafBlocks) << "runs of " << group;
            if (group == 4) {
                EXPECT_LT(wide.blocks.size(), leafBlocks);  // here some runs of three or four fit fewer
            }
        }
    }
}

// The one-step appendMesh (what flatten uses) uploads exactly what prepareMesh then appendMesh does, with
// and without uvs, computed normals or given ones, after another mesh.
TEST(AppendMesh, OneStepEqualsPrepareThenAppendByteForByte) {
    const Affine3 world = then(makeScale(Vec3(2, 1, 1)), makeRotation(normalize(Vec3(1, 2, 3)), 0.8f));
    for (const MeshData& m : {indexedMesh(tessellateSphere(Vec3(0), 1.0f, 12, 24)), quad(false), quad(true)}) {
        SceneArrays twoStep, oneStep;
        appendMesh(prepareMesh(m, Affine3{}), twoStep);
        appendMesh(m, Affine3{}, oneStep);
        appendMesh(prepareMesh(m, world), twoStep);
        appendMesh(m, world, oneStep);
        auto same = [](const auto& a, const auto& b) {
            return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
        };
        EXPECT_TRUE(same(twoStep.triangles, oneStep.triangles));
        EXPECT_TRUE(same(twoStep.triangleCorners, oneStep.triangleCorners));
        EXPECT_TRUE(same(twoStep.meshNodes, oneStep.meshNodes));
        EXPECT_TRUE(same(twoStep.meshes, oneStep.meshes));
    }
}

#ifndef NDEBUG
// prepareMesh relies on the MeshData contract of scene/obj_reader.h: a debug build stops on a mesh that
// breaks it instead of reading past its arrays.
TEST(PrepareMeshDeathTest, AssertsTheObjMeshContract) {
    MeshData m = quad(false);
    m.corners.set(4, {m.corners.position(4), 7, m.corners.uv(4)});  // one normal, index 7
    EXPECT_DEATH(prepareMesh(m, Affine3{}), "contract");
}
#endif

}  // namespace
}  // namespace trazo
