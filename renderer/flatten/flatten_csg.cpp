// CSG flattening (host): post-order nodes; leaf transform = CSG block ∘ operations (outer to inner) ∘
// leaf transforms ∘ the map from the canonical shape to the primitive's own parameters.
#include "flatten/flatten_csg.h"

#include <cmath>

#include "core/aabb.h"
#include "objects/csg.h"
#include "scene/transform_checks.h"

namespace trazo {

namespace {

// Canonical shape -> the primitive as its parameters place it, before the node's own transforms.
Affine3 primitiveFromCanonical(const CsgNode& node) {
    switch (node.kind) {
        case CsgNode::Kind::Sphere: return then(makeScale(Vec3(node.radius)), makeTranslation(node.center));
        case CsgNode::Kind::Cylinder: {
            const Vec3 axis = normalize(node.axis);
            const Vec3 u = anyOrthonormal(axis);
            const Vec3 w = cross(u, axis);
            Affine3 m;
            for (int i = 0; i < 3; ++i) m.row[i] = Vec3(u[i] * node.radius, axis[i] * node.height, w[i] * node.radius);
            m.translation = node.base;
            return m;
        }
        default: return Affine3{};  // Box: the unit cube itself
    }
}

Aabb leafBounds(CsgLeafShape shape, const Affine3& worldFromObject) {
    const Vec3 lo = shape == CsgLeafShape::Sphere ? Vec3(-1, -1, -1)
                    : shape == CsgLeafShape::Box  ? Vec3(-0.5f, -0.5f, -0.5f)
                                                  : Vec3(-1, 0, -1);
    const Vec3 hi = shape == CsgLeafShape::Box ? Vec3(0.5f, 0.5f, 0.5f) : Vec3(1, 1, 1);
    Aabb b;
    for (int c = 0; c < 8; ++c)
        b.grow(worldFromObject.applyToPoint(Vec3((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z)));
    return b.padded();
}

struct Flattener {
    const CsgTree& tree;
    std::vector<CsgNodeData>& nodes;
    uint32_t first;

    // Appends the sub-tree in post-order; returns its root's index within the object.
    uint32_t visit(int32_t index, const Affine3& worldFromParent) {
        const CsgNode& node = tree.nodes[size_t(index)];
        const Affine3 worldFromNode = then(composeTransforms(node.transforms), worldFromParent);
        CsgNodeData data{};
        switch (node.kind) {
            case CsgNode::Kind::Union: data.op = CsgOp::Union; break;
            case CsgNode::Kind::Intersection: data.op = CsgOp::Intersection; break;
            case CsgNode::Kind::Difference: data.op = CsgOp::Difference; break;
            default: data.op = CsgOp::Leaf;
        }
        Aabb b;
        uint32_t left = 0, right = 0;
        if (data.op != CsgOp::Leaf) {
            left = visit(node.left, worldFromNode);
            right = visit(node.right, worldFromNode);
            const CsgNodeData& l = at(left);
            const CsgNodeData& r = at(right);
            if (data.op == CsgOp::Union) b = {min(l.boundsMin, r.boundsMin), max(l.boundsMax, r.boundsMax)};
            else if (data.op == CsgOp::Intersection) b = Aabb{max(l.boundsMin, r.boundsMin), min(l.boundsMax, r.boundsMax)}.padded();
            else b = {l.boundsMin, l.boundsMax};
        } else {
            data.shape = node.kind == CsgNode::Kind::Sphere ? CsgLeafShape::Sphere
                         : node.kind == CsgNode::Kind::Box  ? CsgLeafShape::Box
                                                            : CsgLeafShape::Cylinder;
            const Affine3 worldFromObject = then(primitiveFromCanonical(node), worldFromNode);
            data.objectFromWorld = inverse(worldFromObject);
            data.worldFromObject = worldFromObject;
            b = leafBounds(data.shape, worldFromObject);
        }
        data.boundsMin = b.min;
        data.boundsMax = b.max;
        const uint32_t self = (uint32_t)nodes.size() - first;
        data.parent = self;  // until the parent is appended
        nodes.push_back(data);
        if (data.op != CsgOp::Leaf) {
            at(left).parent = at(right).parent = self;
            at(left).isLeftChild = 1;
        }
        return self;
    }

    CsgNodeData& at(uint32_t local) { return nodes[first + local]; }
};

}  // namespace

CsgShape flattenCsg(const Csg& csg, std::vector<CsgNodeData>& nodes) {
    Flattener f{*csg.tree, nodes, (uint32_t)nodes.size()};
    f.visit(csg.tree->root, composeTransforms(csg.transforms));
    return CsgShape{f.first, (uint32_t)nodes.size() - f.first};
}

bool appendObject(const Csg& csg, SceneArrays& out, uint32_t& index) {
    if (!csg.tree) return false;
    index = (uint32_t)out.csgs.size();
    out.csgs.push_back(flattenCsg(csg, out.csgNodes));
    return true;
}

Aabb hostBounds(const Csg& c) {
    if (!c.tree || c.tree->root < 0) return Aabb{};
    Csg bare;  // the tree without the block's own transforms: flattenCsg's root box, then the 8 corners moved
    bare.tree = c.tree;
    std::vector<CsgNodeData> nodes;
    const CsgShape shape = flattenCsg(bare, nodes);
    const CsgNodeData& root = nodes[shape.firstNode + shape.nodeCount - 1];
    Aabb b;
    b.grow(root.boundsMin);
    b.grow(root.boundsMax);
    return transformedBox(b, c.transforms);
}

}  // namespace trazo
