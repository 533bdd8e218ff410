// flattenCsg(): a host CSG tree -> post-order CsgNodeData with every transform folded into each leaf.
#pragma once

#include "flatten/scene_arrays.h"
#include "scene/scene.h"

namespace trazo {

// Appends the tree's nodes to `nodes` and returns the object (node range and world bounds).
CsgShape flattenCsg(const Csg& csg, std::vector<CsgNodeData>& nodes);

}  // namespace trazo
