#include "accel/collapse_bvh.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace trazo {

namespace {

float binaryNodeArea(const BvhNode& node) { return Aabb{node.boundsMin, node.boundsMax}.surfaceArea(); }

void setLane(WideBvhNode& node, int lane, Vec3 boundsMin, Vec3 boundsMax, uint32_t ref) {
    for (int axis = 0; axis < 3; ++axis) {
        node.bounds[axis][0][lane] = boundsMin[axis];
        node.bounds[axis][1][lane] = boundsMax[axis];
    }
    node.child[lane] = ref;
}

WideBvhNode emptyWideNode() {
    WideBvhNode node{};
    const float inf = std::numeric_limits<float>::infinity();
    for (int lane = 0; lane < kBvhWidth; ++lane) setLane(node, lane, Vec3(inf), Vec3(-inf), kBvhEmptyLane);
    return node;
}

uint32_t leafRefOf(const BvhNode& leaf) {
    if (leaf.primCount > kBvhMaxLeafSize || leaf.firstOrChild >= kBvhMaxFirstPrimitive)
        throw std::length_error("collapseBvh: a leaf is too large or starts too far to fit a child reference");
    return bvhLeafRef(leaf.firstOrChild, leaf.primCount);
}

}  // namespace

std::vector<WideBvhNode> collapseBvh(const Bvh& bvh) {
    std::vector<WideBvhNode> out;
    if (bvh.nodes.empty()) return out;
    const std::vector<BvhNode>& in = bvh.nodes;
    out.reserve(in.size() / 2 + 1);
    out.push_back(emptyWideNode());
    if (in[0].primCount > 0) {
        setLane(out[0], 0, in[0].boundsMin, in[0].boundsMax, leafRefOf(in[0]));
        return out;
    }
    // (binary interior node, the wide node that takes its children), depth first.
    std::vector<std::pair<uint32_t, uint32_t>> pending{{0u, 0u}};
    while (!pending.empty()) {
        const auto [binary, wide] = pending.back();
        pending.pop_back();
        uint32_t lanes[kBvhWidth] = {in[binary].firstOrChild, in[binary].firstOrChild + 1};
        int count = 2;
        while (count < kBvhWidth) {
            int open = -1;
            for (int i = 0; i < count; ++i)
                if (in[lanes[i]].primCount == 0 && (open < 0 || binaryNodeArea(in[lanes[i]]) > binaryNodeArea(in[lanes[open]])))
                    open = i;
            if (open < 0) break;
            const uint32_t left = in[lanes[open]].firstOrChild;
            lanes[open] = left;
            lanes[count++] = left + 1;
        }
        // Children are pushed in reverse so the first lane's subtree is laid out right after this node.
        uint32_t refs[kBvhWidth];
        for (int i = 0; i < count; ++i) {
            const BvhNode& c = in[lanes[i]];
            if (c.primCount > 0) {
                refs[i] = leafRefOf(c);
            } else {
                refs[i] = (uint32_t)out.size();
                out.push_back(emptyWideNode());
            }
        }
        for (int i = 0; i < count; ++i) setLane(out[wide], i, in[lanes[i]].boundsMin, in[lanes[i]].boundsMax, refs[i]);
        for (int i = count - 1; i >= 0; --i)
            if (!bvhIsLeaf(refs[i])) pending.push_back({lanes[i], refs[i]});
    }
    return out;
}

Aabb wideNodeBounds(const WideBvhNode& node) {
    Aabb b;
    for (int lane = 0; lane < kBvhWidth; ++lane) {
        if (node.child[lane] == kBvhEmptyLane) continue;
        b.grow(Vec3(node.bounds[0][0][lane], node.bounds[1][0][lane], node.bounds[2][0][lane]));
        b.grow(Vec3(node.bounds[0][1][lane], node.bounds[1][1][lane], node.bounds[2][1][lane]));
    }
    return b;
}

uint32_t wideBvhStackNeed(const WideBvhNode* nodes, size_t count) {
    // Depth first, the root at 0: every child follows its parent, so one backward sweep sees children first.
    std::vector<uint32_t> need(count, 0);
    for (size_t i = count; i-- > 0;) {
        uint32_t children = 0, deepest = 0;
        for (uint32_t ref : nodes[i].child) {
            if (ref == kBvhEmptyLane) continue;
            ++children;
            if (!bvhIsLeaf(ref)) deepest = std::max(deepest, need[ref]);
        }
        need[i] = (children > 0 ? children - 1 : 0) + deepest;
    }
    return count ? need[0] : 0;
}

uint32_t wideBvhDepth(const std::vector<WideBvhNode>& nodes) {
    if (nodes.empty()) return 0;
    uint32_t deepest = 0;
    std::vector<std::pair<uint32_t, uint32_t>> pending{{0u, 0u}};  // (node, depth)
    while (!pending.empty()) {
        const auto [index, depth] = pending.back();
        pending.pop_back();
        for (uint32_t ref : nodes[index].child) {
            if (ref == kBvhEmptyLane) continue;
            if (bvhIsLeaf(ref)) deepest = std::max(deepest, depth + 1);
            else pending.push_back({ref, depth + 1});
        }
    }
    return deepest;
}

}  // namespace trazo
