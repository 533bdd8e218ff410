// Tests of the BVH: structure invariants, depth limits, determinism, traversal against brute force, and a
// closed sphere that no ray may pass through.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <thread>
#include <vector>

#include "accel/bvh_build.h"
#include "accel/bvh_traverse.h"
#include "accel/collapse_bvh.h"
#include "core/thread_pool.h"
#include "geometry/intersect_triangle_leaf.h"
#include "support/counter_uniform.h"
#include "support/tessellate.h"

namespace trazo {
namespace {

std::vector<Aabb> boundsOf(const std::vector<Vec3>& tris) {
    std::vector<Aabb> bounds(tris.size() / 3);
    for (size_t i = 0; i < bounds.size(); ++i) bounds[i] = triangleBounds(tris[3 * i], tris[3 * i + 1], tris[3 * i + 2]);
    return bounds;
}

// A triangle list with its BVH and the triangles in BVH order, as the renderer holds them and tests them
// (a leaf at a time).
struct TriangleBvh {
    std::vector<Vec3> tris;
    Bvh bvh;
    std::vector<WideBvhNode> nodes;  // what is traversed
    std::vector<MeshTriangle> ordered;

    explicit TriangleBvh(std::vector<Vec3> t, BvhBuildOptions options = triangleBvhOptions()) : tris(std::move(t)) {
        bvh = buildBvh(boundsOf(tris), options);
        nodes = collapseBvh(bvh);
        for (uint32_t id : bvh.primitiveOrder) ordered.push_back({tris[3 * id], tris[3 * id + 1], tris[3 * id + 2]});
    }

    // Closest hit; `index` is the original triangle index.
    bool closest(const Ray& ray, float tMin, float& tMax, uint32_t& index, TriangleHit& hit) const {
        const TriangleRay tr = makeTriangleRay(ray);
        uint32_t found = 0;
        const bool any = traverseClosest(nodes.data(), ray, tMin, tMax, [&](uint32_t first, uint32_t count, float& t) {
            uint32_t which;
            if (!intersectTriangleLeaf(tr, ordered.data() + first, count, tMin, t, hit, which)) return false;
            t = hit.t;
            found = first + which;
            return true;
        });
        if (any) index = bvh.primitiveOrder[found];
        return any;
    }

    bool occluded(const Ray& ray, float tMin, float tMax) const {
        const TriangleRay tr = makeTriangleRay(ray);
        return traverseAny(nodes.data(), ray, tMin, tMax, [&](uint32_t first, uint32_t count, float t) {
            return triangleLeafBlocks(tr, ordered.data() + first, count, tMin, t);
        });
    }
};

bool bruteClosest(const std::vector<Vec3>& tris, const Ray& ray, float tMin, float& tMax, uint32_t& index,
                  TriangleHit& hit) {
    const TriangleRay tr = makeTriangleRay(ray);
    bool any = false;
    for (uint32_t i = 0; 3 * i < tris.size(); ++i) {
        TriangleHit th;
        if (intersectTriangle(tr, tris[3 * i], tris[3 * i + 1], tris[3 * i + 2], tMin, tMax, th)) {
            tMax = th.t;
            hit = th;
            index = i;
            any = true;
        }
    }
    return any;
}

// Checks every invariant the traversal and the renderer rely on; returns the leaf count.
void expectValidStructure(const Bvh& bvh, const std::vector<Aabb>& bounds, uint32_t maxLeafSize) {
    const size_t n = bounds.size();
    ASSERT_EQ(bvh.primitiveOrder.size(), n);
    std::vector<uint32_t> sorted = bvh.primitiveOrder;
    std::sort(sorted.begin(), sorted.end());
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i) << "primitiveOrder is not a permutation";
    if (n == 0) {
        EXPECT_TRUE(bvh.nodes.empty());
        return;
    }
    ASSERT_FALSE(bvh.nodes.empty());
    // Walk from the root carrying the ancestors' boxes; each primitive must fit in every one of them.
    struct Item { uint32_t node, depth; };
    std::vector<Item> stack{{0, 0}};
    std::vector<uint32_t> covered(n, 0);
    std::vector<uint32_t> visits(bvh.nodes.size(), 0);
    std::vector<Aabb> path(kMaxBvhDepth + 2);
    auto toAabb = [](const BvhNode& node) { Aabb b; b.min = node.boundsMin; b.max = node.boundsMax; return b; };
    while (!stack.empty()) {
        const Item it = stack.back();
        stack.pop_back();
        ASSERT_LT(it.node, bvh.nodes.size());
        ASSERT_LE(it.depth, kMaxBvhDepth);
        ++visits[it.node];
        const BvhNode& node = bvh.nodes[it.node];
        path[it.depth] = toAabb(node);
        if (node.primCount == 0) {
            ASSERT_GE(node.firstOrChild, 1u);
            ASSERT_LT(node.firstOrChild + 1, bvh.nodes.size());
            for (uint32_t c = node.firstOrChild; c < node.firstOrChild + 2; ++c)
                EXPECT_TRUE(toAabb(node).contains(toAabb(bvh.nodes[c])));
            stack.push_back({node.firstOrChild, it.depth + 1});
            stack.push_back({node.firstOrChild + 1, it.depth + 1});
            continue;
        }
        EXPECT_LE(node.primCount, maxLeafSize);
        ASSERT_LE((size_t)node.firstOrChild + node.primCount, n);
        for (uint32_t i = node.firstOrChild; i < node.firstOrChild + node.primCount; ++i) {
            ++covered[i];
            const Aabb& prim = bounds[bvh.primitiveOrder[i]];
            for (uint32_t d = 0; d <= it.depth; ++d)
                ASSERT_TRUE(path[d].contains(prim)) << "primitive " << bvh.primitiveOrder[i] << " outside depth " << d;
        }
    }
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(covered[i], 1u) << "position " << i << " not in exactly one leaf";
    for (size_t i = 0; i < visits.size(); ++i) ASSERT_EQ(visits[i], 1u) << "node " << i << " unreachable or shared";
}

// The wide nodes of collapseBvh (or widenBvh's eight-wide ones): every node reached once, every primitive
// position in exactly one leaf (the binary leaves, unchanged), each child box holding every primitive below it,
// no deeper than the binary tree. Returns the depth of the deepest leaf.
template <class Node>
uint32_t expectValidWideStructure(const Bvh& bvh, const std::vector<Node>& nodes, const std::vector<Aabb>& bounds) {
    constexpr int Width = int(sizeof(Node::child) / sizeof(uint32_t));
    const size_t n = bounds.size();
    if (n == 0) {
        EXPECT_TRUE(nodes.empty());
        return 0;
    }
    EXPECT_FALSE(nodes.empty());
    if (nodes.empty()) return 0;
    struct Item { uint32_t node, depth; };
    std::vector<Item> stack{{0, 0}};
    std::vector<uint32_t> covered(n, 0), visits(nodes.size(), 0);
    uint32_t deepest = 0;
    // The primitives below a reference (a leaf's range, or all leaves under a node).
    auto primitivesBelow = [&](uint32_t ref, auto&& self, std::vector<uint32_t>& out) -> void {
        if (bvhIsLeaf(ref)) {
            for (uint32_t i = bvhLeafFirst(ref); i < bvhLeafFirst(ref) + bvhLeafCount(ref); ++i) out.push_back(i);
            return;
        }
        for (uint32_t c : nodes[ref].child)
            if (c != kBvhEmptyLane) self(c, self, out);
    };
    while (!stack.empty()) {
        const Item it = stack.back();
        stack.pop_back();
        EXPECT_LT(it.node, nodes.size());
        if (it.node >= nodes.size()) return 0;
        ++visits[it.node];
        const Node& node = nodes[it.node];
        int used = 0;
        for (int lane = 0; lane < Width; ++lane) {
            const uint32_t ref = node.child[lane];
            if (ref == kBvhEmptyLane) {
                EXPECT_GT(node.bounds[0][0][lane], node.bounds[0][1][lane]) << "an unused lane's box must be empty";
                continue;
            }
            EXPECT_EQ(used++, lane) << "used lanes come first";
            const Aabb box = laneBox(node, lane);
            std::vector<uint32_t> below;
            primitivesBelow(ref, primitivesBelow, below);
            for (uint32_t i : below) EXPECT_TRUE(box.contains(bounds[bvh.primitiveOrder[i]]));
            if (bvhIsLeaf(ref)) {
                deepest = std::max(deepest, it.depth + 1);
                for (uint32_t i : below) ++covered[i];
            } else {
                stack.push_back({ref, it.depth + 1});
            }
        }
        EXPECT_GE(used, 1);
    }
    for (size_t i = 0; i < n; ++i) EXPECT_EQ(covered[i], 1u) << "position " << i << " not in exactly one leaf";
    for (size_t i = 0; i < visits.size(); ++i) EXPECT_EQ(visits[i], 1u) << "wide node " << i << " unreachable or shared";
    if constexpr (Width == kBvhWidth) {
        EXPECT_EQ(deepest, wideBvhDepth(nodes));
    }
    EXPECT_LE(deepest, std::max(1u, bvhDepth(bvh)));
    return deepest;
}

std::vector<Vec3> concat(std::vector<Vec3> a, const std::vector<Vec3>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// Triangles of `count` random axis-aligned cubes: many faces share planes with node bounds.
std::vector<Vec3> cubes(uint32_t count, uint32_t seed) {
    CounterUniform u(seed);
    std::vector<Vec3> tris;
    for (uint32_t k = 0; k < count; ++k) {
        const Vec3 lo(std::round(u(-8, 8)), std::round(u(-8, 8)), std::round(u(-8, 8)));
        const Vec3 hi = lo + Vec3(std::round(u(1, 3)), std::round(u(1, 3)), std::round(u(1, 3)));
        auto corner = [&](int i) { return Vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
        const int faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
        for (const auto& f : faces)
            tris.insert(tris.end(), {corner(f[0]), corner(f[1]), corner(f[2]), corner(f[0]), corner(f[2]), corner(f[3])});
    }
    return tris;
}

TEST(BvhBuild, ZeroAndOnePrimitive) {
    const Bvh empty = buildBvh({});
    EXPECT_TRUE(empty.nodes.empty());
    EXPECT_TRUE(empty.primitiveOrder.empty());

    const TriangleBvh one({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    ASSERT_EQ(one.bvh.nodes.size(), 1u);
    EXPECT_EQ(one.bvh.nodes[0].primCount, 1u);
    EXPECT_EQ(one.bvh.nodes[0].firstOrChild, 0u);
    EXPECT_EQ(one.bvh.primitiveOrder, std::vector<uint32_t>{0});
    float tMax = INFINITY;
    uint32_t index = 99;
    TriangleHit hit;
    ASSERT_TRUE(one.closest({{0.25f, 0.25f, 2}, {0, 0, -1}}, 0.0f, tMax, index, hit));
    EXPECT_EQ(tMax, 2.0f);
    EXPECT_EQ(index, 0u);
    EXPECT_TRUE(one.occluded({{0.25f, 0.25f, 2}, {0, 0, -1}}, 0.0f, INFINITY));
    EXPECT_FALSE(one.occluded({{0.25f, 0.25f, 2}, {0, 0, -1}}, 0.0f, 2.0f));
    EXPECT_FALSE(one.occluded({{0.75f, 0.75f, 2}, {0, 0, -1}}, 0.0f, INFINITY));
}

TEST(BvhBuild, StructureIsValidOnVariedMeshes) {
    const std::vector<std::vector<Vec3>> meshes = {
        randomTriangleSoup(3000, 1), tessellateSphere({0, 0, 0}, 1.0f, 40, 80), degenerateTriangles(2000, 2),
        cubes(300, 3), concat(tessellateSphere({1, 2, 3}, 0.5f, 16, 32, 0.2f), randomTriangleSoup(100, 4, 5.0f))};
    for (uint32_t leaf : {1u, 4u, 8u}) {
        for (const auto& mesh : meshes) {
            BvhBuildOptions options;
            options.maxLeafSize = leaf;
            const std::vector<Aabb> bounds = boundsOf(mesh);
            const Bvh bvh = buildBvh(bounds, options);
            expectValidStructure(bvh, bounds, leaf);
            EXPECT_LE(bvhDepth(bvh), kMaxBvhDepth);
            if (leaf > kBvhMaxLeafSize) continue;
            const std::vector<WideBvhNode> wide = collapseBvh(bvh);
            expectValidWideStructure(bvh, wide, bounds);
            // Eight wide: the same leaves, no deeper than the binary tree (so kBvh8StackSize bounds a traversal;
            // expectValidWideStructure checks it), and fewer nodes.
            const std::vector<WideBvhNode8> wide8 = widenBvh(wide.data(), wide.size());
            expectValidWideStructure(bvh, wide8, bounds);
            EXPECT_LT(wide8.size(), wide.size());
        }
    }
}

WideBvhNode8 emptyNode8() {
    WideBvhNode8 node{};
    for (int lane = 0; lane < kBvh8Width; ++lane) {
        for (int axis = 0; axis < 3; ++axis) node.bounds[axis][0][lane] = 1.0f, node.bounds[axis][1][lane] = -1.0f;
        node.child[lane] = kBvhEmptyLane;
    }
    return node;
}

struct EightWide {
    std::vector<WideBvhNode8> nodes;
    std::vector<uint32_t> leaves;

    uint32_t addNode() {  // a lane's reference to a new, empty node
        nodes.push_back(emptyNode8());
        return uint32_t(nodes.size() - 1);
    }
    uint32_t addRun(const std::vector<uint32_t>& run) {  // a lane's reference to `run` of leaves, appended to leaves
        const uint32_t ref = bvhLeafRef(uint32_t(leaves.size()), uint32_t(run.size()));
        leaves.insert(leaves.end(), run.begin(), run.end());
        return ref;
    }
};

// The leaves under binary node i as references, left to right.
std::vector<uint32_t> leavesUnder(const std::vector<BvhNode>& in, uint32_t i) {
    if (in[i].primCount > 0) return {bvhLeafRef(in[i].firstOrChild, in[i].primCount)};
    std::vector<uint32_t> out = leavesUnder(in, in[i].firstOrChild);
    const std::vector<uint32_t> right = leavesUnder(in, in[i].firstOrChild + 1);
    out.insert(out.end(), right.begin(), right.end());
    return out;
}

// Gives `node` the binary nodes `lanes` with their references, and queues the interior ones as (binary node,
// eight-wide node), the first lane's on top, so its subtree is laid out right after the node.
void setBinaryLanes(const std::vector<BvhNode>& in, const std::vector<uint32_t>& lanes,
                    const std::vector<uint32_t>& refs, WideBvhNode8& node,
                    std::vector<std::pair<uint32_t, uint32_t>>& pending) {
    for (size_t i = 0; i < lanes.size(); ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            node.bounds[axis][0][i] = in[lanes[i]].boundsMin[axis];
            node.bounds[axis][1][i] = in[lanes[i]].boundsMax[axis];
        }
        node.child[i] = refs[i];
    }
    for (size_t i = lanes.size(); i-- > 0;)
        if (!bvhIsLeaf(refs[i])) pending.push_back({lanes[i], refs[i]});
}

// An eight-wide tree made top down from binary node 0: each node's lanes the binary nodes lanesOf(binary) gives,
// each lane's reference refOf(lane, tree) (a new node, a run of leaves or a leaf).
template <class LanesOf, class RefOf>
EightWide topDown(const std::vector<BvhNode>& in, LanesOf lanesOf, RefOf refOf) {
    EightWide tree;
    tree.addNode();
    std::vector<std::pair<uint32_t, uint32_t>> pending{{0u, 0u}};  // (binary node, eight-wide node)
    while (!pending.empty()) {
        const auto [binary, at] = pending.back();
        pending.pop_back();
        const std::vector<uint32_t> lanes = lanesOf(binary);
        std::vector<uint32_t> refs;
        for (uint32_t lane : lanes) refs.push_back(refOf(lane, tree));
        setBinaryLanes(in, lanes, refs, tree.nodes[at], pending);
    }
    return tree;
}

// The cost widenBvh minimises, of an eight-wide tree whose leaf lanes name triangles (runs off) or runs of leaves in
// `leaves` (their triangles packed four to a block): Σ area · kWideNodeCost over nodes, Σ area · blocks ·
// kWideBlockCost over leaf lanes.
double wideTreeCost(const EightWide& tree, bool runs) {
    double cost = 0.0;
    for (const WideBvhNode8& node : tree.nodes) {
        cost += wideCostArea(usedLanesBounds(node)) * kWideNodeCost;
        for (int lane = 0; lane < kBvh8Width; ++lane) {
            const uint32_t ref = node.child[lane];
            if (ref == kBvhEmptyLane || !bvhIsLeaf(ref)) continue;
            uint32_t triangles = bvhLeafCount(ref);
            if (runs) {
                triangles = 0;
                for (uint32_t l = 0; l < bvhLeafCount(ref); ++l)
                    triangles += bvhLeafCount(tree.leaves[bvhLeafFirst(ref) + l]);
            }
            cost += wideCostArea(laneBox(node, lane)) * kWideBlockCost * double((triangles + 3) / 4);
        }
    }
    return cost;
}

// The eight-wide tree widenBvh documents, made straight from the binary tree (an independent oracle): of the trees
// whose nodes are binary nodes, each node's lanes the subtrees below it, the one of least cost, each binary node
// weighed as a node, a leaf lane (a leaf, or with runs a subtree of at most `group` leaves) or its children in the
// lanes it may take (memoised per node and lanes; of equal costs the leaf, the fewer lanes, the fewer lanes left).
EightWide widenBinary(const Bvh& bvh, bool runs, uint32_t group) {
    const std::vector<BvhNode>& in = bvh.nodes;
    const double inf = std::numeric_limits<double>::infinity();
    auto isLeaf = [&](uint32_t i) { return in[i].primCount > 0; };
    auto area = [&](uint32_t i) { return wideCostArea(Aabb{in[i].boundsMin, in[i].boundsMax}); };
    struct Weighed {
        double cost[kBvh8Width];
        int how[kBvh8Width];  // as widenBvh's choice: how[0] 1 a node; how[j − 1] 0 fewer lanes or the left's
        int open = 1;
        uint32_t leaves = 0, triangles = 0;
    };
    std::vector<Weighed> w(in.size());
    auto weigh = [&](uint32_t i, auto&& self) -> void {
        Weighed& n = w[i];
        if (isLeaf(i)) {
            n.leaves = 1, n.triangles = in[i].primCount;
            for (int j = 0; j < kBvh8Width; ++j) n.cost[j] = area(i) * kWideBlockCost, n.how[j] = 0;
            return;
        }
        const uint32_t l = in[i].firstOrChild, r = l + 1;
        self(l, self), self(r, self);
        n.leaves = w[l].leaves + w[r].leaves, n.triangles = w[l].triangles + w[r].triangles;
        double split[kBvh8Width + 1];
        int at[kBvh8Width + 1];
        for (int j = 2; j <= kBvh8Width; ++j) {
            split[j] = inf, at[j] = 1;
            for (int k = 1; k < j; ++k) {
                const double c = w[l].cost[k - 1] + w[r].cost[j - k - 1];
                if (c < split[j]) split[j] = c, at[j] = k;
            }
        }
        const double asLeaf =
            n.leaves <= (runs ? group : 1u) ? area(i) * kWideBlockCost * double((n.triangles + 3) / 4) : inf;
        const double asNode = area(i) * kWideNodeCost + split[kBvh8Width];
        n.cost[0] = asNode < asLeaf ? asNode : asLeaf;
        n.how[0] = asNode < asLeaf;
        n.open = at[kBvh8Width];
        for (int j = 2; j <= kBvh8Width; ++j) {
            n.cost[j - 1] = split[j] < n.cost[j - 2] ? split[j] : n.cost[j - 2];
            n.how[j - 1] = split[j] < n.cost[j - 2] ? at[j] : 0;
        }
    };
    weigh(0, weigh);
    // The binary nodes that take the lanes of binary node i given j of them, left to right.
    auto lanesUnder = [&](uint32_t i, int j, auto&& self, std::vector<uint32_t>& out) -> void {
        while (j > 1 && (isLeaf(i) || w[i].how[j - 1] == 0)) --j;
        if (j == 1) {
            out.push_back(i);
            return;
        }
        self(in[i].firstOrChild, w[i].how[j - 1], self, out);
        self(in[i].firstOrChild + 1, j - w[i].how[j - 1], self, out);
    };
    auto lanesOf = [&](uint32_t binary) {
        std::vector<uint32_t> lanes;
        if (isLeaf(binary)) return std::vector<uint32_t>{binary};
        lanesUnder(in[binary].firstOrChild, w[binary].open, lanesUnder, lanes);
        lanesUnder(in[binary].firstOrChild + 1, kBvh8Width - w[binary].open, lanesUnder, lanes);
        return lanes;
    };
    return topDown(in, lanesOf, [&](uint32_t lane, EightWide& tree) {
        if (!isLeaf(lane) && w[lane].how[0] == 1) return tree.addNode();
        if (runs) return tree.addRun(leavesUnder(in, lane));
        return bvhLeafRef(in[lane].firstOrChild, in[lane].primCount);
    });
}

// An eight-wide tree of the binary tree made greedily, as Embree's builders and widenBvh once did: each node takes
// a binary node's children and, while a lane is free, opens the interior child of largest surface area; with
// runs, an interior child left over with at most `group` leaves is one lane naming its leaves in primitive order.
EightWide greedyWideTree(const Bvh& bvh, bool runs, uint32_t group) {
    const std::vector<BvhNode>& in = bvh.nodes;
    auto isLeaf = [&](uint32_t i) { return in[i].primCount > 0; };
    auto area = [&](uint32_t i) { return Aabb{in[i].boundsMin, in[i].boundsMax}.surfaceArea(); };
    auto lanesOf = [&](uint32_t binary) {
        std::vector<uint32_t> lanes;
        if (isLeaf(binary)) lanes = {binary};
        else lanes = {in[binary].firstOrChild, in[binary].firstOrChild + 1};
        for (;;) {
            int widest = -1;
            for (int i = 0; i < (int)lanes.size(); ++i)
                if (!isLeaf(lanes[i]) && lanes.size() < (size_t)kBvh8Width &&
                    (widest < 0 || area(lanes[i]) > area(lanes[widest])))
                    widest = i;
            if (widest < 0) break;
            const uint32_t left = in[lanes[widest]].firstOrChild;
            lanes[widest] = left;
            lanes.push_back(left + 1);
        }
        return lanes;
    };
    return topDown(in, lanesOf, [&](uint32_t lane, EightWide& tree) {
        const std::vector<uint32_t> under = leavesUnder(in, lane);
        if (runs && (isLeaf(lane) || under.size() <= group)) return tree.addRun(under);
        if (isLeaf(lane)) return bvhLeafRef(in[lane].firstOrChild, in[lane].primCount);
        return tree.addNode();
    });
}

// widenBvh regroups each four-wide node's lanes into the binary nodes they were opened from (WideBvhNode::opened),
// so its tree is the one made straight from the binary tree: the same nodes, lanes, boxes and runs.
TEST(WidenBvh, IsTheEightWideTreeOfTheBinaryTree) {
    const std::vector<std::vector<Vec3>> meshes = {
        randomTriangleSoup(3000, 1), tessellateSphere({0, 0, 0}, 1.0f, 40, 80, 0.1f), degenerateTriangles(2000, 2),
        cubes(300, 3), randomTriangleSoup(3, 5), randomTriangleSoup(1, 6)};
    for (const auto& mesh : meshes) {
        const Bvh bvh = buildBvh(boundsOf(mesh), triangleBvhOptions());
        const std::vector<WideBvhNode> wide = collapseBvh(bvh);
        for (const auto& [runs, group] : {std::pair{false, 1u}, {true, 1u}, {true, 2u}, {true, 4u}}) {
            EightWide made;
            widenBvh(wide.data(), wide.size(), made.nodes, runs ? &made.leaves : nullptr, group);
            const EightWide expected = widenBinary(bvh, runs, group);
            ASSERT_EQ(made.nodes.size(), expected.nodes.size()) << mesh.size() / 3 << " triangles, runs of " << group;
            EXPECT_EQ(made.leaves, expected.leaves);
            for (size_t n = 0; n < made.nodes.size(); ++n)
                for (int lane = 0; lane < kBvh8Width; ++lane) {
                    ASSERT_EQ(made.nodes[n].child[lane], expected.nodes[n].child[lane])
                        << "node " << n << " lane " << lane;
                    if (expected.nodes[n].child[lane] == kBvhEmptyLane) continue;
                    for (int axis = 0; axis < 3; ++axis)
                        for (int side = 0; side < 2; ++side)
                            ASSERT_EQ(made.nodes[n].bounds[axis][side][lane],
                                      expected.nodes[n].bounds[axis][side][lane]);
                }
        }
    }
}

// The tree of least cost costs no more than the greedy one (one of the trees it chose from), and usually less.
TEST(WidenBvh, CostsNoMoreThanOpeningTheLargestChild) {
    const std::vector<std::vector<Vec3>> meshes = {
        randomTriangleSoup(3000, 1), tessellateSphere({0, 0, 0}, 1.0f, 40, 80, 0.1f), cubes(300, 3)};
    int cheaper = 0, cases = 0;
    for (const auto& mesh : meshes) {
        const Bvh bvh = buildBvh(boundsOf(mesh), triangleBvhOptions());
        const std::vector<WideBvhNode> wide = collapseBvh(bvh);
        for (const auto& [runs, group] : {std::pair{false, 1u}, {true, 4u}}) {
            EightWide made;
            widenBvh(wide.data(), wide.size(), made.nodes, runs ? &made.leaves : nullptr, group);
            const double least = wideTreeCost(made, runs), greedy = wideTreeCost(greedyWideTree(bvh, runs, group), runs);
            EXPECT_LE(least, greedy * (1.0 + 1e-6)) << mesh.size() / 3 << " triangles, runs " << runs;
            cheaper += least < greedy * 0.99;
            ++cases;
        }
    }
    EXPECT_GE(cheaper, cases / 2) << "the least-cost tree should beat the greedy one by 1 % on most meshes";
}

// Four-wide nodes without a record of their opening (made elsewhere, or the record damaged) are taken as flat:
// the tree is still a valid one over the same leaves.
TEST(WidenBvh, NodesWithoutAnOpeningRecordAreTakenAsFlat) {
    const std::vector<Vec3> mesh = tessellateSphere({0, 0, 0}, 1.0f, 30, 60, 0.1f);
    const std::vector<Aabb> bounds = boundsOf(mesh);
    const Bvh bvh = buildBvh(bounds, triangleBvhOptions());
    std::vector<WideBvhNode> wide = collapseBvh(bvh);
    for (size_t i = 0; i < wide.size(); ++i) wide[i].opened = i % 2 ? 0u : 0xffffffffu;
    const std::vector<WideBvhNode8> wide8 = widenBvh(wide.data(), wide.size());
    expectValidWideStructure(bvh, wide8, bounds);
    EXPECT_LT(wide8.size(), wide.size());
}

TEST(BvhBuild, IdenticalTrianglesGiveABalancedTree) {
    std::vector<Vec3> tris;
    for (int i = 0; i < 10000; ++i) tris.insert(tris.end(), {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const std::vector<Aabb> bounds = boundsOf(tris);
    const Bvh bvh = buildBvh(bounds);
    expectValidStructure(bvh, bounds, 4);
    expectValidWideStructure(bvh, collapseBvh(bvh), bounds);
    // No SAH split exists, so every split is a median: ceil(log2(10000 / 4)) levels.
    EXPECT_LE(bvhDepth(bvh), 12u);
}

// 480 clusters at x = 1.2^i with 2 bins: the upper bin holds only the farthest few clusters, so SAH alone
// peels them off a few per level (depth > 100); the depth rule must switch to medians in time.
TEST(BvhBuild, ExponentialSpacingStaysWithinMaxDepth) {
    std::vector<Aabb> bounds;
    for (int i = 0; i < 480; ++i)
        for (int k = 0; k < 2; ++k) {
            Aabb b;
            const float x = std::pow(1.2f, (float)i);
            b.grow(Vec3(x, 0, 0));
            b.grow(Vec3(x * 1.0001f, 0.5f, 1));
            bounds.push_back(b);
        }
    BvhBuildOptions options;
    options.binCount = 2;
    const Bvh bvh = buildBvh(bounds, options);
    expectValidStructure(bvh, bounds, 4);
    EXPECT_LE(bvhDepth(bvh), kMaxBvhDepth);
    EXPECT_GT(bvhDepth(bvh), 40u) << "input no longer pathological: the test checks nothing";
    const std::vector<WideBvhNode> wide = collapseBvh(bvh);
    expectValidWideStructure(bvh, wide, bounds);
    expectValidWideStructure(bvh, widenBvh(wide.data(), wide.size()), bounds);

    // Traversal of the deep tree: rays along the row of boxes enter all of them, so the stack runs deep.
    // The nearest box a ray enters, and whether it enters any before tMax, must match testing every box.
    CounterUniform u(7);
    for (int i = 0; i < 2000; ++i) {
        // Odd: straight along +x inside the row (enters every box); even: backwards from far out, slightly tilted.
        const bool along = i % 2;
        const Vec3 origin(along ? -1.0f : u(0.0f, 2e37f), along ? u(0.05f, 0.45f) : u(-0.2f, 0.7f),
                          along ? u(0.05f, 0.95f) : u(-0.2f, 1.2f));
        const Ray ray{origin, along ? Vec3(1, 0, 0) : normalize(Vec3(-1.0f, u(-1e-3f, 1e-3f), u(-1e-3f, 1e-3f)))};
        const BoxRay boxRay = makeBoxRay(ray);
        float tBrute = INFINITY, tEntry;
        for (const Aabb& b : bounds)
            if (intersectBounds(boxRay, b.min, b.max, 0.0f, tBrute, tEntry)) tBrute = std::min(tBrute, std::max(tEntry, 1e-30f));
        float tBvh = INFINITY;
        traverseClosest(wide.data(), ray, 0.0f, tBvh, [&](uint32_t first, uint32_t count, float& tMax) {
            bool hit = false;
            for (uint32_t k = first; k < first + count; ++k) {
                const Aabb& b = bounds[bvh.primitiveOrder[k]];
                if (intersectBounds(boxRay, b.min, b.max, 0.0f, tMax, tEntry)) {
                    tMax = std::min(tMax, std::max(tEntry, 1e-30f));
                    hit = true;
                }
            }
            return hit;
        });
        ASSERT_EQ(tBvh, tBrute) << "ray " << i;
        int leaves = 0;
        EXPECT_FALSE(traverseAny(wide.data(), ray, 0.0f, INFINITY, [&](uint32_t, uint32_t, float) { return ++leaves, false; }));
        if (along) {
            EXPECT_GE(leaves, 240) << "a ray along the row should enter most leaves";
        }
    }
}

void expectSameTree(const Bvh& one, const Bvh& many) {
    ASSERT_EQ(one.nodes.size(), many.nodes.size());
    EXPECT_EQ(0, std::memcmp(one.nodes.data(), many.nodes.data(), one.nodes.size() * sizeof(BvhNode)));
    EXPECT_EQ(one.primitiveOrder, many.primitiveOrder);
}

// With the thread cap `threads` (and `pool`, where given).
Bvh buildOn(const std::vector<Aabb>& bounds, unsigned threads, ThreadPool* pool = nullptr) {
    BvhBuildOptions options;
    options.threads = threads;
    options.pool = pool;
    return buildBvh(bounds, options);
}

TEST(BvhBuild, SameTreeWhateverTheThreadCount) {
    const std::vector<Aabb> bounds = boundsOf(randomTriangleSoup(60000, 5));
    const Bvh one = buildOn(bounds, 1);
    for (unsigned threads : {2u, 3u}) expectSameTree(one, buildOn(bounds, threads));
    expectValidStructure(one, bounds, 4);
}

// On a pool of its own, of any size, at any thread cap: the same tree as on one thread.
TEST(BvhBuild, SameTreeOnAGivenPool) {
    const std::vector<Aabb> bounds = boundsOf(randomTriangleSoup(70000, 6));
    const Bvh one = buildOn(bounds, 1);
    for (unsigned poolThreads : {1u, 3u}) {
        ThreadPool pool(poolThreads);
        for (unsigned threads : {0u, 2u, 5u}) expectSameTree(one, buildOn(bounds, threads, &pool));
    }
}

// Nearest hits agree with testing every triangle (bitwise distance; the same triangle unless two tie), and
// any-hit agrees with the nearest hit and with the tMax bound.
void expectMatchesBruteForce(const TriangleBvh& scene, const std::vector<Ray>& rays) {
    int hits = 0;
    for (size_t r = 0; r < rays.size(); ++r) {
        const Ray& ray = rays[r];
        float tBvh = INFINITY, tBrute = INFINITY;
        uint32_t iBvh = 0, iBrute = 0;
        TriangleHit hBvh{}, hBrute{};
        const bool bvhHit = scene.closest(ray, 0.0f, tBvh, iBvh, hBvh);
        const bool bruteHit = bruteClosest(scene.tris, ray, 0.0f, tBrute, iBrute, hBrute);
        ASSERT_EQ(bvhHit, bruteHit) << "ray " << r;
        ASSERT_EQ(scene.occluded(ray, 0.0f, INFINITY), bruteHit) << "ray " << r;
        if (!bruteHit) continue;
        ++hits;
        ASSERT_EQ(tBvh, tBrute) << "ray " << r;
        if (iBvh == iBrute) {
            EXPECT_EQ(hBvh.b1, hBrute.b1);
            EXPECT_EQ(hBvh.b2, hBrute.b2);
        }
        // Nothing strictly closer than the nearest hit; the nearest itself once tMax passes it.
        ASSERT_FALSE(scene.occluded(ray, 0.0f, tBrute)) << "ray " << r;
        ASSERT_TRUE(scene.occluded(ray, 0.0f, std::nextafter(tBrute, INFINITY))) << "ray " << r;
        // A tMin past the nearest hit finds the next one, as brute force does.
        float tNextBvh = INFINITY, tNextBrute = INFINITY;
        const bool nextBvh = scene.closest(ray, tBrute, tNextBvh, iBvh, hBvh);
        ASSERT_EQ(nextBvh, bruteClosest(scene.tris, ray, tBrute, tNextBrute, iBrute, hBrute)) << "ray " << r;
        if (nextBvh) {
            ASSERT_EQ(tNextBvh, tNextBrute) << "ray " << r;
        }
    }
    EXPECT_GT(hits, (int)rays.size() / 10) << "too few hits to test anything";
}

std::vector<Ray> randomRays(uint32_t count, uint32_t seed, float originSpread, float targetSpread) {
    CounterUniform u(seed);
    std::vector<Ray> rays;
    for (uint32_t i = 0; i < count; ++i) {
        const Vec3 origin = u.point(originSpread);
        // Half aimed at the mesh, half in any direction (from inside, these hit too).
        rays.push_back({origin, i % 2 ? u.point(targetSpread) - origin : u.direction()});
    }
    return rays;
}

// The highest stack slot any traversal of `rays` writes, closest-hit and any-hit alike: slots start as a
// sentinel that no node reference or leaf can equal.
int stackHighWater(const TriangleBvh& scene, const std::vector<Ray>& rays) {
    constexpr uint32_t kUntouched = kBvhEmptyLane;
    std::vector<bvh_detail::StackEntry> closest(kBvhStackSize, {kUntouched, 0.0f});
    std::vector<uint32_t> any(kBvhStackSize, kUntouched);
    for (const Ray& ray : rays) {
        ClosestStack c{closest.data(), kBvhStackSize, 0};
        AnyStack a{any.data(), kBvhStackSize, 0};
        float tMax = INFINITY;
        traverseClosest(scene.nodes.data(), ray, 0.0f, tMax, c, [&](uint32_t, uint32_t, float&) { return false; });
        traverseAny(scene.nodes.data(), ray, 0.0f, INFINITY, a, [&](uint32_t, uint32_t, float) { return false; });
        EXPECT_EQ(c.size, 0);
        EXPECT_EQ(a.size, 0);
    }
    int high = 0;
    for (int i = 0; i < kBvhStackSize; ++i)
        if (closest[i].ref != kUntouched || any[i] != kUntouched) high = i + 1;
    return high;
}

// wideBvhStackNeed is what the CUDA upload checks against the kernels' fixed stack: no traversal may go past
// it. Leaves that never hit make every ray visit every node it enters, the deepest use of the stack.
TEST(BvhTraverse, StackNeedBoundsEveryTraversal) {
    const TriangleBvh soup(randomTriangleSoup(3000, 50));
    const TriangleBvh sphere(tessellateSphere({0, 0, 0}, 1.0f, 48, 96));
    const TriangleBvh degenerate(concat(degenerateTriangles(2000, 51), randomTriangleSoup(300, 52)));
    for (const TriangleBvh* scene : {&soup, &sphere, &degenerate}) {
        const uint32_t need = wideBvhStackNeed(scene->nodes.data(), scene->nodes.size());
        EXPECT_LE(need, 3 * wideBvhDepth(scene->nodes));
        const int high = stackHighWater(*scene, randomRays(3000, 53, 2.0f, 1.0f));
        EXPECT_LE(high, (int)need);
        EXPECT_GE(high, (int)need / 4) << "the bound should be near what traversals use, not just safe";
    }
    EXPECT_EQ(wideBvhStackNeed(nullptr, 0), 0u);
}

TEST(BvhTraverse, ClosestMatchesBruteForceOnSoups) {
    for (uint32_t leaf : {1u, 4u}) {
        BvhBuildOptions options;
        options.maxLeafSize = leaf;
        expectMatchesBruteForce(TriangleBvh(randomTriangleSoup(2000, 10), options), randomRays(1500, 11, 2.0f, 1.0f));
        expectMatchesBruteForce(TriangleBvh(concat(randomTriangleSoup(500, 12, 0.3f), randomTriangleSoup(50, 13, 4.0f)), options),
                                randomRays(1500, 14, 3.0f, 0.5f));
    }
}

TEST(BvhTraverse, ClosestMatchesBruteForceOnDegenerateAndSliverTriangles) {
    expectMatchesBruteForce(TriangleBvh(concat(degenerateTriangles(3000, 20), randomTriangleSoup(200, 21))),
                            randomRays(2000, 22, 2.0f, 1.0f));
}

TEST(BvhTraverse, ClosestMatchesBruteForceOnSpheres) {
    expectMatchesBruteForce(TriangleBvh(tessellateSphere({0.1f, -0.2f, 0.3f}, 1.0f, 32, 64)), randomRays(2000, 30, 2.0f, 1.0f));
    expectMatchesBruteForce(TriangleBvh(tessellateSphere({0, 0, 0}, 1.0f, 24, 48, 0.3f)), randomRays(2000, 31, 0.5f, 1.0f));
}

// Rays along the axes, starting on the cubes' face planes: zero direction components with origins on the
// node slabs (NaN in the slab test) must keep the node, since the brute force finds hits on the edges.
TEST(BvhTraverse, AxisAlignedRaysOnSlabPlanesMatchBruteForce) {
    const std::vector<Vec3> tris = cubes(200, 40);
    const TriangleBvh scene(tris);
    CounterUniform u(41);
    std::vector<Ray> rays;
    for (int i = 0; i < 3000; ++i) {
        // Along one axis, the other two coordinates on a random cube's face planes (or inside it).
        const uint32_t cube = (uint32_t)u(0.0f, 199.99f);
        const Vec3 lo = tris[36 * cube], hi = tris[36 * cube + 3 * 2 + 2];  // corners 0 and 7 (see cubes())
        const int axis = i % 3;
        Vec3 origin, direction(0, 0, 0);
        origin[axis] = u(0.0f, 1.0f) < 0.5f ? -12.0f : 12.0f;
        direction[axis] = origin[axis] < 0.0f ? 1.0f : -1.0f;
        for (int k = 1; k < 3; ++k) {
            const int c = (axis + k) % 3;
            const float pick = u(0.0f, 3.0f);
            origin[c] = pick < 1.0f ? lo[c] : (pick < 2.0f ? hi[c] : u(lo[c], hi[c]));
        }
        rays.push_back({origin, direction});
    }
    expectMatchesBruteForce(scene, rays);
}

// The host's SSE child test and the scalar one the device runs must agree bit for bit: same mask, same entry
// distances. Boxes and rays are drawn rich in the awkward cases: flat and empty boxes, coordinates on shared
// planes, zero direction components (infinite inverses, NaN products) and signed zeros.
TEST(BvhTraverse, SseChildTestMatchesScalarBitForBit) {
#if TRAZO_HOST_SSE
    CounterUniform u(50);
    auto coordinate = [&]() {
        const float pick = u(0.0f, 4.0f);
        return pick < 1.0f ? std::round(u(-3.0f, 3.0f)) : (pick < 1.2f ? -0.0f : u(-3.0f, 3.0f));
    };
    const float inf = INFINITY;
    int hits = 0;
    for (int trial = 0; trial < 200000; ++trial) {
        WideBvhNode node{};
        for (int lane = 0; lane < kBvhWidth; ++lane)
            for (int axis = 0; axis < 3; ++axis) {
                float lo = coordinate(), hi = coordinate();
                if (lo > hi) std::swap(lo, hi);
                if (u(0.0f, 1.0f) < 0.05f) lo = hi;                      // flat
                if (u(0.0f, 1.0f) < 0.02f) lo = inf, hi = -inf;          // empty
                node.bounds[axis][0][lane] = lo;
                node.bounds[axis][1][lane] = hi;
            }
        Vec3 origin(coordinate(), coordinate(), coordinate()), direction = u.direction();
        for (int axis = 0; axis < 3; ++axis)
            if (u(0.0f, 1.0f) < 0.2f) direction[axis] = u(0.0f, 1.0f) < 0.5f ? 0.0f : -0.0f;
        const bvh_detail::NodeRay r = bvh_detail::makeNodeRay({origin, direction});
        const float tMin = u(0.0f, 1.0f) < 0.5f ? 0.0f : u(0.0f, 2.0f);
        const float tMax = u(0.0f, 1.0f) < 0.5f ? inf : u(0.0f, 6.0f);
        float sse[kBvhWidth], scalar[kBvhWidth];
        const unsigned maskSse = bvh_detail::intersectChildrenSse(r, node, tMin, tMax, sse);
        const unsigned maskScalar = bvh_detail::intersectChildrenScalar(r, node, tMin, tMax, scalar);
        ASSERT_EQ(maskSse, maskScalar) << "trial " << trial;
        ASSERT_EQ(0, std::memcmp(sse, scalar, sizeof sse)) << "trial " << trial;
        hits += maskScalar != 0;
    }
    EXPECT_GT(hits, 20000) << "too few boxes entered to test anything";
#else
    GTEST_SKIP() << "this build has no SSE child test (not x86-64, or a device compile)";
#endif
}

// The host's shortcut for one or two children entered must push and return exactly what the sorting
// insertion does (which child is nearest on a tie decides which of two equally near triangles is kept).
TEST(BvhTraverse, NearestChildShortcutMatchesTheSort) {
#if TRAZO_HOST_SSE
    CounterUniform u(51);
    const std::vector<WideBvhNode> nodes(104);  // what the interior references 100–103 point to (prefetched)
    int twoChildren = 0, ties = 0;
    for (int trial = 0; trial < 100000; ++trial) {
        WideBvhNode node{};
        float tEntry[kBvhWidth];
        for (int lane = 0; lane < kBvhWidth; ++lane) {
            const float pick = u(0.0f, 1.0f);
            node.child[lane] = pick < 0.1f ? kBvhEmptyLane : (pick < 0.5f ? bvhLeafRef(7 * lane, 1 + lane % 4) : 100u + lane);
            tEntry[lane] = std::round(u(0.0f, 3.0f));  // few distinct values: many ties
        }
        const unsigned mask = (unsigned)u(0.0f, 16.0f) & 0xfu;
        bvh_detail::StackEntry sorted[kBvhWidth], shortcut[kBvhWidth];
        int sortedSize = 0, shortcutSize = 0;
        const uint32_t a = bvh_detail::pushFartherChildren(node, mask, tEntry, sorted, sortedSize, kBvhWidth);
        const uint32_t b = bvh_detail::nearestChildPushOthers(nodes.data(), node, mask, tEntry, shortcut, shortcutSize,
                                                                 kBvhWidth);
        ASSERT_EQ(a, b) << "trial " << trial;
        ASSERT_EQ(sortedSize, shortcutSize) << "trial " << trial;
        for (int i = 0; i < sortedSize; ++i) {
            ASSERT_EQ(sorted[i].ref, shortcut[i].ref) << "trial " << trial;
            ASSERT_EQ(sorted[i].tEntry, shortcut[i].tEntry) << "trial " << trial;
        }
        unsigned entered = 0;
        for (int lane = 0; lane < kBvhWidth; ++lane)
            if ((mask >> lane & 1) && node.child[lane] != kBvhEmptyLane) entered |= 1u << lane;
        if (__builtin_popcount(entered) == 2) {
            ++twoChildren;
            const int first = __builtin_ctz(entered), second = 31 - __builtin_clz(entered);
            ties += tEntry[first] == tEntry[second];
        }
    }
    EXPECT_GT(twoChildren, 10000) << "too few nodes with two children entered";
    EXPECT_GT(ties, 1000) << "too few ties between two children";
#else
    GTEST_SKIP() << "this build has no host shortcut (not x86-64, or a device compile)";
#endif
}

// 1,000,000 rays from outside a closed tessellated sphere towards points inside it: each must hit, and be
// blocked before reaching its target. Rays aimed at the mesh's vertices stress the shared edges.
TEST(BvhWatertight, ClosedSphereLetsNoRayThrough) {
    const TriangleBvh sphere(tessellateSphere({0.3f, -0.1f, 0.2f}, 1.0f, 48, 96));
    const Vec3 center(0.3f, -0.1f, 0.2f);
    constexpr uint32_t kRays = 1000000;
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::atomic<uint32_t> leaks{0}, unblocked{0};
    auto work = [&](unsigned part) {
        uint32_t localLeaks = 0, localUnblocked = 0;
        CounterUniform u(1000 + part);
        for (uint32_t i = part; i < kRays; i += threads) {
            Vec3 origin = center + u.direction() * u(1.5f, 4.0f), target = center + u.direction() * u(0.0f, 0.9f);
            if (i % 2) {
                // Through a mesh vertex (where 6 triangles meet, or a pole's fan) from within 45° of its
                // normal, so the ray enters the solid there: only a crack could let it through.
                target = sphere.tris[hashU32(i) % sphere.tris.size()];
                origin = target + normalize(normalize(target - center) + u.direction() * 0.7f) * u(0.5f, 3.0f);
            }
            const Ray ray{origin, target - origin};
            float tMax = INFINITY;
            uint32_t index;
            TriangleHit hit;
            localLeaks += !sphere.closest(ray, 0.0f, tMax, index, hit);
            // Aimed strictly inside, the surface lies before t = 1.
            if (i % 2 == 0) localUnblocked += !sphere.occluded(ray, 0.0f, 1.0f);
        }
        leaks += localLeaks;
        unblocked += localUnblocked;
    };
    std::vector<std::thread> pool;
    for (unsigned p = 1; p < threads; ++p) pool.emplace_back(work, p);
    work(0);
    for (std::thread& t : pool) t.join();
    EXPECT_EQ(leaks.load(), 0u);
    EXPECT_EQ(unblocked.load(), 0u);
}

}  // namespace
}  // namespace trazo
