#include "accel/collapse_bvh.h"

#include <algorithm>
#include <bit>
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

// Some lanes of a four-wide node: the binary node they were collapsed from (widenBvh).
struct LaneGroup {
    uint32_t node, lanes;
};

// Whether `opened` describes the node's lanes: lanes 0 .. 2 + steps − 1 used, each step opening a lane that
// existed then. Otherwise widenBvh takes the node as flat (each lane a child of the binary node).
bool opensDescribeLanes(const WideBvhNode& node) {
    const uint32_t used = usedLaneMask(node);
    const int lanes = std::popcount(used), steps = (int)(node.opened & 3u);
    if (used != (1u << lanes) - 1 || lanes != 2 + steps) return false;
    for (int k = 0; k < steps; ++k)
        if (((node.opened >> (2 + 2 * k)) & 3u) >= (uint32_t)(2 + k)) return false;
    return true;
}

// Splits `group` (two or more lanes of `node`) into the groups of the binary node's children, replaying
// collapseBvh's openings backwards (a lane opened at step k gave its right child to lane 2 + k); for a flat
// node, into single lanes. Returns the count.
int splitLanes(const WideBvhNode& node, uint32_t group, uint32_t parts[kBvhWidth]) {
    if (opensDescribeLanes(node)) {
        uint32_t member[kBvhWidth] = {1u, 2u, 4u, 8u};  // what each lane's binary node holds, as steps are undone
        for (int k = (int)(node.opened & 3u) - 1; k >= 0; --k) {
            const uint32_t lane = (node.opened >> (2 + 2 * k)) & 3u;
            if ((member[lane] | member[2 + k]) == group) {
                parts[0] = member[lane], parts[1] = member[2 + k];
                return 2;
            }
            member[lane] |= member[2 + k];
        }
        if ((member[0] | member[1]) == group) {
            parts[0] = member[0], parts[1] = member[1];
            return 2;
        }
    }
    int n = 0;
    for (uint32_t m = group; m; m &= m - 1) parts[n++] = 1u << std::countr_zero(m);
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
        uint32_t opened = 0;  // WideBvhNode::opened
        while (count < kBvhWidth) {
            int open = -1;
            for (int i = 0; i < count; ++i)
                if (in[lanes[i]].primCount == 0 && (open < 0 || binaryNodeArea(in[lanes[i]]) > binaryNodeArea(in[lanes[open]])))
                    open = i;
            if (open < 0) break;
            opened |= (uint32_t)open << (2 + 2 * (count - 2));
            const uint32_t left = in[lanes[open]].firstOrChild;
            lanes[open] = left;
            lanes[count++] = left + 1;
        }
        out[wide].opened = opened | (uint32_t)(count - 2);
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
    if (leaves && groupLeaves > kBvhMaxLeafRun)
        throw std::invalid_argument("widenBvh: runs longer than kBvhMaxLeafRun");
    const size_t base = out.size();  // the root; references count from it
    // The leaves below each node. Depth first, the root at 0: one backward sweep sees children first.
    std::vector<uint32_t> leavesBelow(count, 0);
    for (size_t i = count; i-- > 0;)
        for (uint32_t ref : nodes[i].child)
            if (ref != kBvhEmptyLane) leavesBelow[i] += bvhIsLeaf(ref) ? 1 : leavesBelow[ref];
    // A binary node of the tree the four-wide one was collapsed from is a LaneGroup: some lanes of a four-wide node,
    // or one lane naming a four-wide node, which stands for all of that node's lanes (read only when needed: on
    // a large mesh each read of a node is a cache miss).
    auto isLeaf = [&](LaneGroup g) {
        return std::popcount(g.lanes) == 1 && bvhIsLeaf(nodes[g.node].child[std::countr_zero(g.lanes)]);
    };
    auto lanesOf = [&](LaneGroup g) {  // the same binary node as lanes of the node whose lanes are its children
        if (std::popcount(g.lanes) == 1) {
            const uint32_t ref = nodes[g.node].child[std::countr_zero(g.lanes)];
            if (!bvhIsLeaf(ref)) return LaneGroup{ref, usedLaneMask(nodes[ref])};
        }
        return g;
    };
    auto leafCount = [&](LaneGroup g) {
        uint32_t n = 0;
        for (uint32_t m = g.lanes; m; m &= m - 1) {
            const uint32_t ref = nodes[g.node].child[std::countr_zero(m)];
            n += bvhIsLeaf(ref) ? 1 : leavesBelow[ref];
        }
        return n;
    };
    // A lane of the eight-wide node being made, and what choosing the lane to open asks of it.
    struct Lane {
        LaneGroup group;
        Aabb box;
        float area;
        int parts;  // the lanes its children take (2; a flat node's lanes; 0 for a leaf); a guess until opened
    };
    auto makeLane = [&](LaneGroup g) {
        Lane lane{g, lanesBounds(nodes[g.node], g.lanes), 0.0f, 0};  // one lane: exactly its binary node's box
        lane.area = lane.box.surfaceArea();
        if (std::popcount(g.lanes) > 1) lane.parts = opensDescribeLanes(nodes[g.node]) ? 2 : std::popcount(g.lanes);
        else if (const uint32_t ref = nodes[g.node].child[std::countr_zero(g.lanes)]; !bvhIsLeaf(ref)) {
            lane.parts = 2;  // the four-wide node below is not read yet, only fetched
            __builtin_prefetch(nodes + ref);
            __builtin_prefetch(reinterpret_cast<const char*>(nodes + ref) + 64);
        }
        return lane;
    };
    // A run of leaves in `leaves`, in primitive order, as a lane's reference.
    auto leafRun = [&](LaneGroup g) {
        uint32_t refs[kBvhMaxLeafRun];
        uint32_t n = 0;
        auto collect = [&](uint32_t node, uint32_t lanes, auto&& self) -> void {
            for (uint32_t m = lanes; m; m &= m - 1) {
                const uint32_t ref = nodes[node].child[std::countr_zero(m)];
                if (bvhIsLeaf(ref)) refs[n++] = ref;
                else self(ref, usedLaneMask(nodes[ref]), self);
            }
        };
        collect(g.node, g.lanes, collect);
        for (uint32_t i = 1; i < n; ++i)  // insertion sort: a handful
            for (uint32_t j = i; j > 0 && bvhLeafFirst(refs[j]) < bvhLeafFirst(refs[j - 1]); --j)
                std::swap(refs[j], refs[j - 1]);
        if (leaves->size() + n > kBvhMaxFirstPrimitive)
            throw std::length_error("widenBvh: more leaves than a child reference can name");
        const uint32_t first = (uint32_t)leaves->size();
        leaves->insert(leaves->end(), refs, refs + n);
        return bvhLeafRef(first, n);
    };
    out.reserve(base + count);
    out.push_back(emptyWideNode<WideBvhNode8>());
    // (binary node, the eight-wide node that takes its children), depth first.
    std::vector<std::pair<LaneGroup, uint32_t>> pending{{LaneGroup{0u, usedLaneMask(nodes[0])}, 0u}};
    while (!pending.empty()) {
        const auto [seed, made] = pending.back();
        pending.pop_back();
        Lane lanes[kBvh8Width];
        int used = 0;
        // Opens binary node g into lanes[i] and new lanes, if its children fit; else returns how many they are.
        auto open = [&](LaneGroup g, int i) {
            g = lanesOf(g);
            uint32_t masks[kBvhWidth] = {};
            const int parts = splitLanes(nodes[g.node], g.lanes, masks);
            if (used - 1 + parts > kBvh8Width) return parts;
            lanes[i] = makeLane(LaneGroup{g.node, masks[0]});
            for (int k = 1; k < parts; ++k) lanes[used++] = makeLane(LaneGroup{g.node, masks[k]});
            return 0;
        };
        if (isLeaf(seed)) {
            lanes[used++] = makeLane(seed);
        } else {
            ++used;
            open(seed, 0);  // at most four children: they fit
        }
        // While lanes are left, open the interior child of largest surface area (the one a ray is most likely to
        // enter); what is left stays a lane.
        for (;;) {
            int widest = -1;
            for (int i = 0; i < used; ++i)
                if (lanes[i].parts > 0 && used - 1 + lanes[i].parts <= kBvh8Width &&
                    (widest < 0 || lanes[i].area > lanes[widest].area))
                    widest = i;
            if (widest < 0) break;
            if (const int parts = open(lanes[widest].group, widest)) lanes[widest].parts = parts;  // guessed wrong
        }
        // A leaf left over is a lane; with `leaves`, so is a subtree of at most groupLeaves leaves.
        uint32_t refs[kBvh8Width];
        for (int i = 0; i < used; ++i) {
            const LaneGroup g = lanes[i].group;
            if (isLeaf(g)) {
                refs[i] = leaves ? leafRun(g) : nodes[g.node].child[std::countr_zero(g.lanes)];
            } else if (leaves && leafCount(g) <= groupLeaves) {
                refs[i] = leafRun(g);
            } else {
                refs[i] = (uint32_t)(out.size() - base);
                out.push_back(emptyWideNode<WideBvhNode8>());
            }
        }
        WideBvhNode8& node = out[base + made];
        for (int i = 0; i < used; ++i) setLane(node, i, lanes[i].box.min, lanes[i].box.max, refs[i]);
        // Children are pushed in reverse so the first lane's subtree is laid out right after this node.
        for (int i = used - 1; i >= 0; --i)
            if (!bvhIsLeaf(refs[i])) pending.push_back({lanes[i].group, refs[i]});
    }
}

std::vector<WideBvhNode8> widenBvh(const WideBvhNode* nodes, size_t count) {
    std::vector<WideBvhNode8> out;
    widenBvh(nodes, count, out);
    return out;
}

Aabb wideNodeBounds(const WideBvhNode& node) { return usedLanesBounds(node); }

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
