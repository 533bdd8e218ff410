// The CSG block on the host: the tree its .csg file holds (SPEC §4), shared between blocks that name the same
// file, the block's struct and transform steps, and the editor's operations on one. Flattening folds every
// transform into the leaves of the kernels' CsgShape (objects/csg.h; flatten/flatten_csg.cpp).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "objects/csg.h"
#include "scene/object_basics.h"

namespace trazo {

struct SceneArrays;

// A CSG tree from a .csg file (SPEC §4). Nodes are stored in one array; the root is `root`.
struct CsgNode {
    enum class Kind { Sphere, Box, Cylinder, Union, Difference, Intersection } kind = Kind::Sphere;
    // Primitive parameters (Sphere: center/radius; Cylinder: base/axis/height/radius; Box: none).
    Vec3 center{0, 0, 0};
    float radius = 1.0f;
    Vec3 base{0, 0, 0};
    Vec3 axis{0, 1, 0};
    float height = 1.0f;
    std::vector<TransformStep> transforms;  // for operations: applied to the whole sub-tree
    int32_t left = -1, right = -1;           // node indices, operations only
    SourceLocation where;
};

struct CsgTree {
    std::vector<CsgNode> nodes;
    int32_t root = -1;
};

struct Csg {
    static constexpr bool kReadFromFile = true;  // added by addObjectFromFile, never by newObject
    int32_t material = kDefaultMaterial;
    std::string source;  // resolved path
    std::vector<TransformStep> transforms;  // [ext] placement of the whole object
    std::shared_ptr<const CsgTree> tree;
    SourceLocation where;
};

// Appends the solid's post-order nodes to out.csgNodes and its CsgShape to out.csgs; false for a CSG block
// whose tree did not load (flatten/flatten_csg.cpp).
bool appendObject(const Csg& csg, SceneArrays& out, uint32_t& index);

// The tree's bounds (its flattened root's) with the block's transforms applied to their 8 corners; empty for a
// solid that is empty everywhere or whose file did not load (flatten/flatten_csg.cpp).
Aabb hostBounds(const Csg& c);
inline void translate(Csg& c, Vec3 delta) { translateSteps(c.transforms, delta); }
inline std::optional<Csg> newObject(KindTag<Csg>, Vec3, float) { return std::nullopt; }
inline void scaleAboutOrigin(Csg& c, double factor) { scaleSteps(c.transforms, factor); }

}  // namespace trazo
