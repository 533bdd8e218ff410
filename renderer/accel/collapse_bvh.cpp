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

// A binary node's subtree as widenBvh weighs it: its least SAH cost (area-weighted node visits and leaf-block tests)
// when it takes at most j lanes of an eight-wide node, cost[j − 1] for j = 1 .. 8.
struct SubtreeCost {
    double cost[kBvh8Width];
    uint32_t leaves, triangles;
};

// The choices that cost that, in one word: bit 0, as one lane, a node of its own (1) or a leaf lane (0); for j = 2 ..
// 8, three bits from 3j − 5: 0 as in j − 1 lanes, k > 0 its children in k and j − k lanes; bits 22–24, as a node, the
// lanes its left child takes (the right one the rest of eight).
constexpr uint32_t choiceSplit(uint32_t choice, int j) { return (choice >> (3 * j - 5)) & 7u; }
constexpr uint32_t choiceOpen(uint32_t choice) { return (choice >> 22) & 7u; }

// The choices of a four-wide node's binary nodes of two or more lanes (at most three), by their lanes.
struct NodeChoices {
    uint32_t choice[3];
    uint8_t lanes[3];
};

// Combines the children's costs into the parent's (Ylitie, Karras and Laine 2017, §4.1) and returns its choices.
// `area` and `mayBeNode` are the parent's; a subtree of at most `maxRun` leaves may be one leaf lane.
uint32_t weighChildren(const SubtreeCost& l, const SubtreeCost& r, double area, bool mayBeNode, uint32_t maxRun,
                       SubtreeCost& out) {
    const double inf = std::numeric_limits<double>::infinity();
    out.leaves = l.leaves + r.leaves;
    out.triangles = l.triangles + r.triangles;
    double split[kBvh8Width + 1];
    uint32_t at[kBvh8Width + 1];
    for (int j = 2; j <= kBvh8Width; ++j) {
        split[j] = inf, at[j] = 1;
        for (int k = 1; k < j; ++k)
            if (const double c = l.cost[k - 1] + r.cost[j - k - 1]; c < split[j]) split[j] = c, at[j] = (uint32_t)k;
    }
    const double asLeaf = out.leaves <= maxRun ? area * kWideBlockCost * double((out.triangles + 3) / 4) : inf;
    const double asNode = mayBeNode ? area * kWideNodeCost + split[kBvh8Width] : inf;
    uint32_t choice = (asNode < asLeaf ? 1u : 0u) | at[kBvh8Width] << 22;
    out.cost[0] = std::min(asLeaf, asNode);
    for (int j = 2; j <= kBvh8Width; ++j) {
        const bool opens = split[j] < out.cost[j - 2];
        out.cost[j - 1] = opens ? split[j] : out.cost[j - 2];
        if (opens) choice |= at[j] << (3 * j - 5);
    }
    return choice;
}

// widenBvh on one four-wide tree. A binary node of the tree the four-wide one was collapsed from is a LaneGroup:
// some lanes of a four-wide node, or one lane naming a four-wide node, which stands for all of that node's lanes.
class Widener {
public:
    Widener(const WideBvhNode* nodes, size_t count, uint32_t maxRun, std::vector<uint32_t>* leaves)
        : nodes_(nodes), maxRun_(maxRun), leaves_(leaves), subtree_(count), choices_(count) {}

    // Bottom up: the nodes are depth first, so a backward sweep sees children first. Each four-wide node's binary
    // nodes are weighed inside it; subtree_[i] is node i's whole subtree.
    void weighAll() {
        for (size_t i = subtree_.size(); i-- > 0;) {
            const uint32_t used = usedLaneMask(nodes_[i]);
            if (used == 0) throw std::invalid_argument("widenBvh: a node without children");
            int slots = 0;
            subtree_[i] = weigh(LaneGroup{(uint32_t)i, used}, true, slots);
        }
    }

    // Top down: each node made takes its binary node's children in the lanes the choices give them.
    void build(std::vector<WideBvhNode8>& out) const {
        const size_t base = out.size();  // the root; references count from it
        out.push_back(emptyWideNode<WideBvhNode8>());
        std::vector<std::pair<LaneGroup, uint32_t>> pending{{canonical(LaneGroup{0u, usedLaneMask(nodes_[0])}), 0u}};
        while (!pending.empty()) {
            const auto [binary, made] = pending.back();
            pending.pop_back();
            const MadeLanes lanes = lanesOf(binary);
            uint32_t refs[kBvh8Width];
            for (int i = 0; i < lanes.used; ++i) refs[i] = laneRef(lanes.group[i], lanes.choice[i], out, base);
            WideBvhNode8& node = out[base + made];
            for (int i = 0; i < lanes.used; ++i) {
                const LaneGroup g = lanes.group[i];
                const Aabb box = lanesBounds(nodes_[g.node], g.lanes);  // exactly its binary node's box
                setLane(node, i, box.min, box.max, refs[i]);
            }
            // Children are pushed in reverse so the first lane's subtree is laid out right after this node.
            for (int i = lanes.used - 1; i >= 0; --i)
                if (!bvhIsLeaf(refs[i])) pending.push_back({lanes.group[i], refs[i]});
        }
    }

private:
    // The lanes of a node made for a binary node, leftmost first, with each one's choices (0 for a leaf): bit 0
    // says whether it is a node.
    struct MadeLanes {
        LaneGroup group[kBvh8Width] = {};
        uint32_t choice[kBvh8Width];
        int used = 0;
    };

    // The binary node's two children, or for a flat node the first lane and the rest (a group weighed, never made
    // a node of its own, so each node made is a binary node and kBvh8StackSize holds). Returns whether the rest
    // may be a node.
    bool children(LaneGroup g, LaneGroup& left, LaneGroup& right) const {
        uint32_t parts[kBvhWidth] = {};
        const int n = splitLanes(nodes_[g.node], g.lanes, parts);
        left = LaneGroup{g.node, parts[0]}, right = LaneGroup{g.node, g.lanes & ~parts[0]};
        return n == 2;
    }

    // The group as the binary node's own lanes, where one lane names a node (and a node of one lane is that lane).
    LaneGroup canonical(LaneGroup g) const {
        while (std::popcount(g.lanes) == 1) {
            const uint32_t ref = nodes_[g.node].child[std::countr_zero(g.lanes)];
            if (bvhIsLeaf(ref)) break;
            g = LaneGroup{ref, usedLaneMask(nodes_[ref])};
        }
        return g;
    }

    static bool isLeaf(LaneGroup g) { return std::popcount(g.lanes) == 1; }  // of a canonical group
    double area(LaneGroup g) const { return wideCostArea(lanesBounds(nodes_[g.node], g.lanes)); }

    // The group's subtree cost; records the choices of each binary node of two or more lanes in its four-wide node's
    // NodeChoices, `slots` of them so far.
    SubtreeCost weigh(LaneGroup g, bool mayBeNode, int& slots) {
        if (std::popcount(g.lanes) == 1) {
            const uint32_t ref = nodes_[g.node].child[std::countr_zero(g.lanes)];
            if (!bvhIsLeaf(ref)) return subtree_[ref];
            SubtreeCost leaf;
            leaf.leaves = 1, leaf.triangles = bvhLeafCount(ref);
            const double oneBlock = area(g) * kWideBlockCost;  // ≤ kBvhMaxLeafSize triangles
            for (double& c : leaf.cost) c = oneBlock;
            return leaf;
        }
        LaneGroup left, right;
        const bool restMayBeNode = children(g, left, right);
        const SubtreeCost l = weigh(left, true, slots), r = weigh(right, restMayBeNode, slots);
        SubtreeCost made;
        NodeChoices& c = choices_[g.node];
        c.choice[slots] = weighChildren(l, r, area(g), mayBeNode, maxRun_, made);
        c.lanes[slots++] = (uint8_t)g.lanes;
        return made;
    }

    uint32_t choiceOf(LaneGroup g) const {
        const NodeChoices& c = choices_[g.node];
        for (int s = 0; s < 3; ++s)
            if (c.lanes[s] == g.lanes) return c.choice[s];
        throw std::logic_error("widenBvh: a binary node that was not weighed");
    }

    // Splits the binary node into lanes as its choices say: each part of 2 .. 8 lanes is split further until the
    // choices keep a part whole.
    MadeLanes lanesOf(LaneGroup binary) const {
        MadeLanes made;
        if (isLeaf(binary)) {  // a tree of one leaf
            made.choice[made.used] = 0;
            made.group[made.used++] = binary;
            return made;
        }
        std::pair<LaneGroup, int> split[2 * kBvh8Width];  // (binary node, the lanes it takes), the leftmost on top
        int size = 0;
        auto splitChildren = [&](LaneGroup g, int lanes, int leftLanes) {
            LaneGroup left, right;
            children(g, left, right);
            split[size++] = {canonical(right), lanes - leftLanes};
            split[size++] = {canonical(left), leftLanes};
        };
        splitChildren(binary, kBvh8Width, (int)choiceOpen(choiceOf(binary)));
        while (size > 0) {
            auto [g, j] = split[--size];
            const uint32_t choice = isLeaf(g) ? 0u : choiceOf(g);
            while (j > 1 && choiceSplit(choice, j) == 0) --j;
            if (j == 1) {
                made.choice[made.used] = choice;
                made.group[made.used++] = g;
            } else {
                splitChildren(g, j, (int)choiceSplit(choice, j));
            }
        }
        return made;
    }

    // A lane's reference: a new node in `out` (counted from `base`), a run of leaves, or the four-wide tree's leaf.
    uint32_t laneRef(LaneGroup g, uint32_t choice, std::vector<WideBvhNode8>& out, size_t base) const {
        if (choice & 1u) {
            out.push_back(emptyWideNode<WideBvhNode8>());
            return (uint32_t)(out.size() - 1 - base);
        }
        return leaves_ ? leafRun(g) : nodes_[g.node].child[std::countr_zero(g.lanes)];
    }

    // A run of leaves in `leaves_`, in primitive order, as a lane's reference.
    uint32_t leafRun(LaneGroup g) const {
        uint32_t refs[kBvhMaxLeafRun];
        uint32_t n = 0;
        auto collect = [&](uint32_t node, uint32_t lanes, auto&& self) -> void {
            for (uint32_t m = lanes; m; m &= m - 1) {
                const uint32_t ref = nodes_[node].child[std::countr_zero(m)];
                if (bvhIsLeaf(ref)) refs[n++] = ref;
                else self(ref, usedLaneMask(nodes_[ref]), self);
            }
        };
        collect(g.node, g.lanes, collect);
        for (uint32_t i = 1; i < n; ++i)  // insertion sort: a handful
            for (uint32_t j = i; j > 0 && bvhLeafFirst(refs[j]) < bvhLeafFirst(refs[j - 1]); --j)
                std::swap(refs[j], refs[j - 1]);
        if (leaves_->size() + n > kBvhMaxFirstPrimitive)
            throw std::length_error("widenBvh: more leaves than a child reference can name");
        const uint32_t first = (uint32_t)leaves_->size();
        leaves_->insert(leaves_->end(), refs, refs + n);
        return bvhLeafRef(first, n);
    }

    const WideBvhNode* nodes_;
    uint32_t maxRun_;
    std::vector<uint32_t>* leaves_;
    std::vector<SubtreeCost> subtree_;
    std::vector<NodeChoices> choices_;
};

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
    Widener widener(nodes, count, leaves ? groupLeaves : 1, leaves);
    widener.weighAll();
    widener.build(out);
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
