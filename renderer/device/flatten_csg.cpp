// CSG flattening (host): post-order nodes; leaf transform = CSG block ∘ operations (outer to inner) ∘
// leaf transforms ∘ the map from the canonical shape to the primitive's own parameters.
#include "device/flatten_csg.h"

#include <cmath>

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

struct Flattener {
    const CsgTree& tree;
    std::vector<CsgNodeData>& nodes;
    uint32_t first;
    Vec3 boundsMin{INFINITY, INFINITY, INFINITY}, boundsMax{-INFINITY, -INFINITY, -INFINITY};

    void visit(int32_t index, const Affine3& worldFromParent) {
        const CsgNode& node = tree.nodes[size_t(index)];
        const Affine3 worldFromNode = then(composeTransforms(node.transforms), worldFromParent);
        CsgNodeData data{};
        switch (node.kind) {
            case CsgNode::Kind::Union: data.op = CsgOp::Union; break;
            case CsgNode::Kind::Intersection: data.op = CsgOp::Intersection; break;
            case CsgNode::Kind::Difference: data.op = CsgOp::Difference; break;
            default: data.op = CsgOp::Leaf;
        }
        if (data.op != CsgOp::Leaf) {
            visit(node.left, worldFromNode);
            visit(node.right, worldFromNode);
        } else {
            data.shape = node.kind == CsgNode::Kind::Sphere ? CsgLeafShape::Sphere
                         : node.kind == CsgNode::Kind::Box  ? CsgLeafShape::Box
                                                            : CsgLeafShape::Cylinder;
            const Affine3 worldFromObject = then(primitiveFromCanonical(node), worldFromNode);
            data.objectFromWorld = inverse(worldFromObject);
            includeBounds(data.shape, worldFromObject);
        }
        nodes.push_back(data);
    }

    void includeBounds(CsgLeafShape shape, const Affine3& worldFromObject) {
        const Vec3 lo = shape == CsgLeafShape::Sphere ? Vec3(-1, -1, -1)
                        : shape == CsgLeafShape::Box  ? Vec3(-0.5f, -0.5f, -0.5f)
                                                      : Vec3(-1, 0, -1);
        const Vec3 hi = shape == CsgLeafShape::Box ? Vec3(0.5f, 0.5f, 0.5f) : Vec3(1, 1, 1);
        for (int c = 0; c < 8; ++c) {
            const Vec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
            const Vec3 p = worldFromObject.applyToPoint(corner);
            boundsMin = min(boundsMin, p);
            boundsMax = max(boundsMax, p);
        }
    }
};

}  // namespace

CsgShape flattenCsg(const Csg& csg, std::vector<CsgNodeData>& nodes) {
    Flattener f{*csg.tree, nodes, (uint32_t)nodes.size()};
    f.visit(csg.tree->root, composeTransforms(csg.transforms));
    // Pad by a relative margin so rounding in the slab test never culls a grazing ray.
    const Vec3 pad = (f.boundsMax - f.boundsMin) * 1e-4f + abs(f.boundsMax) * 1e-6f + abs(f.boundsMin) * 1e-6f;
    return CsgShape{f.first, (uint32_t)nodes.size() - f.first, f.boundsMin - pad, f.boundsMax + pad};
}

}  // namespace trazo
