#include "accel/collapse_bvh.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace trazo {

namespace {

float binaryNodeArea(const BvhNode& node) { return Aabb{node.boundsMin, node.boundsMax}.surfaceArea(); }

// For WideBvhNode and WideBvhNode8 alike: the same layout, four or eight lanes.
template <class Node>
void setLane(Node& node, int lane, Vec3 boundsMin, Vec3 boundsMax, uint32_t ref) {
    for (int axis = 0; axis < 3; ++axis) {
        node.bounds[axis][0][lane] = boundsMin[axis];
        node.bounds[axis][1][lane] = boundsMax[axis];
    }
    node.child[lane] = ref;
}

template <class Node = WideBvhNode>
Node emptyWideNode() {
    Node node{};
    const float inf = std::numeric_limits<float>::infinity();
    for (int lane = 0; lane < int(sizeof(node.child) / sizeof(node.child[0])); ++lane)
        setLane(node, lane, Vec3(inf), Vec3(-inf), kBvhEmptyLane);
    return node;
}

// The box of a four-wide node's child `lane`.
Aabb laneBox(const WideBvhNode& node, int lane) {
    return Aabb{Vec3(node.bounds[0][0][lane], node.bounds[1][0][lane], node.bounds[2][0][lane]),
                Vec3(node.bounds[0][1][lane], node.bounds[1][1][lane], node.bounds[2][1][lane])};
}

// The number of children of a four-wide node whose children are all leaves (they fill its first lanes), else 0.
uint32_t leafOnlyChildren(const WideBvhNode& node) {
    uint32_t n = 0;
    for (uint32_t ref : node.child) {
        if (ref == kBvhEmptyLane) break;
        if (!bvhIsLeaf(ref)) return 0;
        ++n;
    }
    return n;
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

void widenBvh(const WideBvhNode* nodes, size_t count, std::vector<WideBvhNode8>& out, std::vector<uint32_t>* leaves,
              uint32_t groupLeaves) {
    if (count == 0) return;
    const size_t base = out.size();  // the root; references count from it
    // A lane of the node being made: a child of some four-wide node (which node, which of its lanes).
    struct Lane {
        uint32_t node, lane;
    };
    auto laneArea = [&](Lane l) { return laneBox(nodes[l.node], (int)l.lane).surfaceArea(); };
    auto usedLanes = [&](uint32_t node) {
        uint32_t used = 0;
        for (uint32_t ref : nodes[node].child) used += ref != kBvhEmptyLane;
        return used;
    };
    out.reserve(base + count);
    out.push_back(emptyWideNode<WideBvhNode8>());
    // (four-wide node, the eight-wide node that takes its children), depth first.
    std::vector<std::pair<uint32_t, uint32_t>> pending{{0u, 0u}};
    while (!pending.empty()) {
        const auto [seed, made] = pending.back();
        pending.pop_back();
        Lane lanes[kBvh8Width];
        int used = 0;
        for (uint32_t lane = 0; lane < (uint32_t)kBvhWidth; ++lane)
            if (nodes[seed].child[lane] != kBvhEmptyLane) lanes[used++] = {seed, lane};
        for (;;) {
            int open = -1;
            float openArea = 0.0f;
            for (int i = 0; i < used; ++i) {
                const uint32_t ref = nodes[lanes[i].node].child[lanes[i].lane];
                if (bvhIsLeaf(ref) || used - 1 + (int)usedLanes(ref) > kBvh8Width) continue;
                const float area = laneArea(lanes[i]);
                if (open < 0 || area > openArea) open = i, openArea = area;
            }
            if (open < 0) break;
            const uint32_t opened = nodes[lanes[open].node].child[lanes[open].lane];
            bool first = true;
            for (uint32_t lane = 0; lane < (uint32_t)kBvhWidth; ++lane) {
                if (nodes[opened].child[lane] == kBvhEmptyLane) continue;
                lanes[first ? open : used++] = {opened, lane};
                first = false;
            }
        }
        // A run of leaves in `leaves`, as a lane's reference.
        auto leafRun = [&](const uint32_t* refs, uint32_t n) {
            if (leaves->size() + n > kBvhMaxFirstPrimitive)
                throw std::length_error("widenBvh: more leaves than a child reference can name");
            const uint32_t first = (uint32_t)leaves->size();
            leaves->insert(leaves->end(), refs, refs + n);
            return bvhLeafRef(first, n);
        };
        uint32_t refs[kBvh8Width];
        for (int i = 0; i < used; ++i) {
            const uint32_t ref = nodes[lanes[i].node].child[lanes[i].lane];
            if (bvhIsLeaf(ref)) {
                refs[i] = leaves ? leafRun(&ref, 1) : ref;
            } else if (const uint32_t n = leaves ? leafOnlyChildren(nodes[ref]) : 0; n > 0 && n <= groupLeaves) {
                refs[i] = leafRun(nodes[ref].child, n);
            } else {
                refs[i] = (uint32_t)(out.size() - base);
                out.push_back(emptyWideNode<WideBvhNode8>());
            }
        }
        WideBvhNode8& node = out[base + made];
        for (int i = 0; i < used; ++i) {
            const Aabb box = laneBox(nodes[lanes[i].node], (int)lanes[i].lane);
            setLane(node, i, box.min, box.max, refs[i]);
        }
        // Children are pushed in reverse so the first lane's subtree is laid out right after this node.
        for (int i = used - 1; i >= 0; --i)
            if (!bvhIsLeaf(refs[i])) pending.push_back({nodes[lanes[i].node].child[lanes[i].lane], refs[i]});
    }
}

std::vector<WideBvhNode8> widenBvh(const WideBvhNode* nodes, size_t count) {
    std::vector<WideBvhNode8> out;
    widenBvh(nodes, count, out);
    return out;
}

Aabb wideNodeBounds(const WideBvhNode& node) {
    Aabb b;
    for (int lane = 0; lane < kBvhWidth; ++lane) {
        if (node.child[lane] == kBvhEmptyLane) continue;
        const Aabb box = laneBox(node, lane);
        b.grow(box.min);
        b.grow(box.max);
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
