// Ray–CSG intersection against analytic answers and a brute-force point-membership oracle.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "flatten/flatten_csg.h"
#include "objects/csg.h"

namespace trazo {
namespace {

CsgNode sphereNode(Vec3 center, float radius) {
    CsgNode n;
    n.kind = CsgNode::Kind::Sphere;
    n.center = center;
    n.radius = radius;
    return n;
}

CsgNode boxNode(Vec3 scale) {
    CsgNode n;
    n.kind = CsgNode::Kind::Box;
    n.transforms.push_back({TransformStep::Kind::Scale, scale, 0.0f});
    return n;
}

CsgNode opNode(CsgNode::Kind kind, int left, int right) {
    CsgNode n;
    n.kind = kind;
    n.left = left;
    n.right = right;
    return n;
}

struct Flat {
    std::vector<CsgNodeData> nodes;
    CsgShape shape;
};

Flat flatTree(std::vector<CsgNode> nodes, int root) {
    auto tree = std::make_shared<CsgTree>();
    tree->nodes = std::move(nodes);
    tree->root = root;
    Csg csg;
    csg.tree = tree;
    Flat f;
    f.shape = flattenCsg(csg, f.nodes);
    return f;
}

bool hitCsg(const Flat& f, Vec3 o, Vec3 d, ShapeHit& hit) {
    return intersectCsg(f.shape, f.nodes.data(), Ray{o, d}, 0.0f, INFINITY, hit);
}

TEST(CsgAnalytic, SphereMinusSphereShowsTheCavityWithAFlippedNormal) {
    const Flat f = flatTree({sphereNode({0, 0, 0}, 1), sphereNode({0, 0, 1}, 0.5f),
                             opNode(CsgNode::Kind::Difference, 0, 1)}, 2);
    ShapeHit hit;
    ASSERT_TRUE(hitCsg(f, {0, 0, 5}, {0, 0, -1}, hit));
    EXPECT_NEAR(hit.t, 4.5f, 1e-5f);  // the subtracted sphere's far side, z = 0.5
    EXPECT_NEAR(hit.normal.z, 1.0f, 1e-5f);
    ASSERT_TRUE(hitCsg(f, {0, 5, 0}, {0, -1, 0}, hit));  // away from the cavity: the big sphere
    EXPECT_NEAR(hit.t, 4.0f, 1e-5f);
    EXPECT_NEAR(hit.normal.y, 1.0f, 1e-5f);
}

TEST(CsgAnalytic, BoxIntersectSphereRoundsTheCorners) {
    const Flat f = flatTree({boxNode({2, 2, 2}), sphereNode({0, 0, 0}, 1.2f),
                             opNode(CsgNode::Kind::Intersection, 0, 1)}, 2);
    ShapeHit hit;
    ASSERT_TRUE(hitCsg(f, {5, 0, 0}, {-1, 0, 0}, hit));  // the face: the sphere reaches beyond it
    EXPECT_NEAR(hit.t, 4.0f, 1e-5f);
    EXPECT_NEAR(hit.normal.x, 1.0f, 1e-5f);
    const Vec3 d = normalize(Vec3(-1, -1, -1));
    ASSERT_TRUE(hitCsg(f, Vec3(5, 5, 5), d, hit));  // the corner: cut by the sphere
    EXPECT_NEAR(hit.t, std::sqrt(75.0f) - 1.2f, 1e-4f);
    EXPECT_NEAR(dot(hit.normal, -d), 1.0f, 1e-5f);
}

TEST(CsgAnalytic, UnionOfOverlappingSpheresFromInsideAndOutside) {
    const Flat f = flatTree({sphereNode({-0.5f, 0, 0}, 1), sphereNode({0.5f, 0, 0}, 1),
                             opNode(CsgNode::Kind::Union, 0, 1)}, 2);
    ShapeHit hit;
    ASSERT_TRUE(hitCsg(f, {0, 0, 0}, {1, 0, 0}, hit));  // from inside: the exit at x = 1.5
    EXPECT_NEAR(hit.t, 1.5f, 1e-5f);
    EXPECT_NEAR(hit.normal.x, 1.0f, 1e-5f);
    ASSERT_TRUE(hitCsg(f, {-5, 0, 0}, {1, 0, 0}, hit));  // from outside: no inner surface in between
    EXPECT_NEAR(hit.t, 3.5f, 1e-5f);
    EXPECT_NEAR(hit.normal.x, -1.0f, 1e-5f);
    EXPECT_FALSE(hitCsg(f, {0, 0, 5}, {0, 1, 0}, hit));
}

CsgNode movedBox(Vec3 center) {
    CsgNode n = boxNode({1, 1, 1});
    n.transforms.push_back({TransformStep::Kind::Translation, center, 0.0f});
    return n;
}

TEST(CsgAnalytic, CoplanarFacesOfAUnionAreNoSurface) {
    const Flat f = flatTree({movedBox({-0.5f, 0, 0}), movedBox({0.5f, 0, 0}), opNode(CsgNode::Kind::Union, 0, 1)}, 2);
    ShapeHit hit;
    ASSERT_TRUE(hitCsg(f, {-5, 0.1f, 0.2f}, {1, 0, 0}, hit));
    EXPECT_NEAR(hit.t, 4.0f, 1e-5f);
    ASSERT_TRUE(hitCsg(f, {-0.25f, 0.1f, 0.2f}, {1, 0, 0}, hit));  // from inside, across the shared face
    EXPECT_NEAR(hit.t, 1.25f, 1e-5f);
    EXPECT_NEAR(hit.normal.x, 1.0f, 1e-5f);
}

TEST(CsgAnalytic, TouchingSolidsIntersectInNothing) {
    const Flat f =
        flatTree({movedBox({-0.5f, 0, 0}), movedBox({0.5f, 0, 0}), opNode(CsgNode::Kind::Intersection, 0, 1)}, 2);
    ShapeHit hit;
    EXPECT_FALSE(hitCsg(f, {-5, 0.1f, 0.2f}, {1, 0, 0}, hit));
}

TEST(CsgAnalytic, TangentRayTouchesASphereDifferenceOnlyAtItsSurface) {
    // A ray tangent to the subtracted sphere (grazing its cavity's rim) hits the outer sphere normally.
    const Flat f = flatTree({sphereNode({0, 0, 0}, 1), sphereNode({0, 0, 0}, 0.5f),
                             opNode(CsgNode::Kind::Difference, 0, 1)}, 2);
    ShapeHit hit;
    ASSERT_TRUE(hitCsg(f, {-5, 0.5f, 0}, {1, 0, 0}, hit));
    EXPECT_NEAR(hit.t, 5.0f - std::sqrt(0.75f), 1e-5f);
    EXPECT_NEAR(hit.normal.y, 0.5f, 1e-5f);
}

// Brute-force oracle: point membership of the flattened tree, in double, swept in post-order.
bool insideLeaf(const CsgNodeData& n, Vec3 pWorld) {
    const Vec3 p = n.objectFromWorld.applyToPoint(pWorld);
    switch (n.shape) {
        case CsgLeafShape::Sphere: return double(p.x) * p.x + double(p.y) * p.y + double(p.z) * p.z < 1.0;
        case CsgLeafShape::Box: return std::fabs(p.x) < 0.5f && std::fabs(p.y) < 0.5f && std::fabs(p.z) < 0.5f;
        case CsgLeafShape::Cylinder: return double(p.x) * p.x + double(p.z) * p.z < 1.0 && p.y > 0.0f && p.y < 1.0f;
    }
    return false;
}

bool inside(const Flat& f, Vec3 p) {
    std::vector<bool> stack;
    for (const CsgNodeData& n : f.nodes) {
        if (n.op == CsgOp::Leaf) {
            stack.push_back(insideLeaf(n, p));
            continue;
        }
        const bool right = stack.back();
        stack.pop_back();
        const bool left = stack.back();
        stack.back() = csgInside(n.op, left, right);
    }
    return stack.back();
}

int randomTree(std::mt19937& rng, std::vector<CsgNode>& nodes, int depth) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::uniform_real_distribution<float> scale(0.4f, 1.3f);
    CsgNode n;
    // Depth up to 6 while the tree stays within the 63-node limit: later sub-trees become leaves.
    if (depth == 0 || (depth < 6 && u(rng) < -0.3f) || nodes.size() > 40) {
        const int kind = int((u(rng) + 1.0f) * 1.5f) % 3;
        n.kind = kind == 0 ? CsgNode::Kind::Sphere : kind == 1 ? CsgNode::Kind::Box : CsgNode::Kind::Cylinder;
        n.radius = scale(rng) * 0.8f;
        n.center = Vec3(u(rng), u(rng), u(rng)) * 0.5f;
        n.base = Vec3(u(rng), u(rng) - 1.0f, u(rng)) * 0.5f;
        n.axis = normalize(Vec3(u(rng), u(rng) + 2.0f, u(rng)));
        n.height = scale(rng) * 1.5f;
    } else {
        const int kind = int((u(rng) + 1.0f) * 1.5f) % 3;
        n.kind = kind == 0 ? CsgNode::Kind::Union : kind == 1 ? CsgNode::Kind::Intersection : CsgNode::Kind::Difference;
        n.left = randomTree(rng, nodes, depth - 1);
        n.right = randomTree(rng, nodes, depth - 1);
    }
    n.transforms.push_back({TransformStep::Kind::Scale, Vec3(scale(rng), scale(rng), scale(rng)), 0.0f});
    n.transforms.push_back({TransformStep::Kind::Rotation, Vec3(u(rng), u(rng), u(rng) + 0.1f), u(rng) * 3.0f});
    n.transforms.push_back({TransformStep::Kind::Translation, Vec3(u(rng), u(rng), u(rng)) * 0.3f, 0.0f});
    nodes.push_back(n);
    return int(nodes.size()) - 1;
}

// Random trees (depth up to 6, 63 nodes at most) and random rays, from outside and from inside: the
// first hit agrees with marching the membership oracle and refining the first change by bisection,
// and the normal points from inside to outside.
TEST(CsgOracle, RandomTreesAgreeWithPointMembership) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int rays = 0, agreed = 0, hits = 0;
    for (int t = 0; t < 48; ++t) {
        std::vector<CsgNode> nodes;
        const int root = randomTree(rng, nodes, 6);
        ASSERT_LE(nodes.size(), 63u);
        const Flat f = flatTree(nodes, root);
        for (int r = 0; r < 60; ++r) {
            const Vec3 o = r % 3 == 0 ? Vec3(u(rng), u(rng), u(rng)) * 0.5f : normalize(Vec3(u(rng), u(rng), u(rng))) * 4.0f;
            const Vec3 d = normalize(Vec3(u(rng), u(rng), u(rng)) * 0.8f - o * (r % 3 == 0 ? 0.0f : 1.0f));
            const float step = 2e-3f, tEnd = 9.0f;
            const bool start = inside(f, o);
            float tOracle = -1;
            for (float s = step; s < tEnd; s += step) {
                if (inside(f, o + d * s) != start) {
                    float lo = s - step, hi = s;
                    for (int k = 0; k < 30; ++k) {
                        const float mid = 0.5f * (lo + hi);
                        (inside(f, o + d * mid) != start ? hi : lo) = mid;
                    }
                    tOracle = hi;
                    break;
                }
            }
            ShapeHit hit;
            const bool found = hitCsg(f, o, d, hit);
            ++rays;
            bool ok;
            if (!found) {
                ok = tOracle < 0;
            } else {
                ++hits;
                const float e = 1e-3f;
                const bool boundary = inside(f, o + d * (hit.t - e)) != inside(f, o + d * (hit.t + e));
                const Vec3 p = o + d * hit.t;
                const bool outward = !inside(f, p + hit.normal * e) && inside(f, p - hit.normal * e);
                // A sliver thinner than the march step may be found first by the exact routine.
                const bool first = tOracle < 0 ? boundary : std::fabs(hit.t - tOracle) < 1e-3f || (hit.t < tOracle && boundary);
                ok = first && boundary && outward;
            }
            agreed += ok;
        }
    }
    std::printf("csg oracle: %d rays, %d hits, %d agreed\n", rays, hits, agreed);
    EXPECT_GT(hits, rays / 5);
    // Tangent grazes can flip the membership test at ε; none else may disagree.
    EXPECT_GE(agreed, rays - rays / 1000) << agreed << " of " << rays;
}

}  // namespace
}  // namespace trazo
