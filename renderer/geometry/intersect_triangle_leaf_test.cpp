// Tests of the leaf test: the host's four-at-once version must find what the device's loop over
// intersectTriangle finds, bit for bit, and any-hit must agree with it.
#include "geometry/intersect_triangle_leaf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "support/counter_uniform.h"
#include "support/tessellate.h"

namespace trazo {
namespace {

std::vector<MeshTriangle> toTriangles(const std::vector<Vec3>& p) {
    std::vector<MeshTriangle> out;
    for (size_t i = 0; i + 2 < p.size(); i += 3) out.push_back({p[i], p[i + 1], p[i + 2]});
    return out;
}

// Leaves drawn from soups, slivers and zero-area triangles, and from a sphere's fans (shared edges and
// vertices, where edge functions are exactly zero and the scalar fallback runs); rays aimed at them.
TEST(TriangleLeaf, FourAtOnceMatchesTheLoopBitForBit) {
    std::vector<MeshTriangle> pool = toTriangles(randomTriangleSoup(400, 1));
    for (const MeshTriangle& t : toTriangles(degenerateTriangles(400, 2))) pool.push_back(t);
    for (const MeshTriangle& t : toTriangles(tessellateSphere({0, 0, 0}, 1.0f, 8, 16))) pool.push_back(t);
    CounterUniform u(3);
    int hits = 0, trials = 0;
    for (size_t first = 0; first + 4 <= pool.size(); ++first) {
        for (uint32_t count = 1; count <= kMaxLeafTriangles; ++count)
            for (int k = 0; k < 6; ++k, ++trials) {
                const MeshTriangle& target = pool[first + (uint32_t)u(0.0f, (float)count - 0.01f)];
                // At a vertex, an edge midpoint or a random interior point, from a random place.
                const float pick = u(0.0f, 3.0f);
                const Vec3 aim = pick < 1.0f ? target.p0
                                             : (pick < 2.0f ? (target.p1 + target.p2) * 0.5f
                                                            : (target.p0 + target.p1 + target.p2) * (1.0f / 3.0f));
                const Vec3 origin = u.point(3.0f);
                const TriangleRay ray = makeTriangleRay({origin, aim - origin});
                const float tMin = k % 3 == 0 ? 0.5f : 0.0f, tMax = k % 2 ? 1.5f : INFINITY;
                TriangleHit leafHit{}, loopHit{};
                uint32_t leafWhich = 99, loopWhich = 99;
                const bool leaf = intersectTriangleLeaf(ray, &pool[first], count, tMin, tMax, leafHit, leafWhich);
                const bool loop = intersectTrianglesLoop(ray, &pool[first], count, tMin, tMax, loopHit, loopWhich);
                ASSERT_EQ(leaf, loop) << "leaf at " << first << ", count " << count;
                ASSERT_EQ(triangleLeafBlocks(ray, &pool[first], count, tMin, tMax), loop);
                if (!loop) continue;
                ++hits;
                ASSERT_EQ(leafWhich, loopWhich);
                ASSERT_EQ(0, std::memcmp(&leafHit, &loopHit, sizeof leafHit));
            }
    }
    EXPECT_GT(hits, trials / 4) << "too few hits to test anything";
}

// Two triangles at the same distance (a duplicated triangle): the first one wins, as in the loop.
TEST(TriangleLeaf, EqualDistancesGoToTheFirstTriangle) {
    const MeshTriangle a{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    const MeshTriangle leaf[3] = {{{5, 5, 5}, {6, 5, 5}, {5, 6, 5}}, a, a};
    TriangleHit hit;
    uint32_t which = 99;
    ASSERT_TRUE(intersectTriangleLeaf(makeTriangleRay({{0, 0, 2}, {0, 0, -1}}), leaf, 3, 0.0f, INFINITY, hit, which));
    EXPECT_EQ(which, 1u);
    EXPECT_EQ(hit.t, 2.0f);
}

}  // namespace
}  // namespace trazo
