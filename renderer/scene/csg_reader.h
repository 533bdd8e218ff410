// CSG reader (host): a .csg file (SPEC §4) → CsgTree, with CSGFILE:LINE errors.
#pragma once

#include <memory>
#include <string>

#include "scene/diagnostic.h"
#include "scene/scene.h"

namespace trazo {

// The most nodes (primitives + operations) a tree may have: the renderer walks CSG trees with a fixed-size
// stack sized from this constant, so larger files are rejected when read.
constexpr int kMaxCsgNodes = 64;

// Nodes keep file order in CsgTree::nodes; operations point at their children by index. The file must
// describe one tree: exactly one node no operation references (the root), every other node referenced
// exactly once (a node shared by two operations, a DAG, is rejected), no cycles, indices in range.
// A `Material` line in a primitive is ignored with a warning (the scene's CSG block gives the material).
// Returns null after reporting any problem.
std::shared_ptr<const CsgTree> readCsgFile(const std::string& path, Diagnostics& diags);

// Same, from text already read; `pathForMessages` names the file in diagnostics.
std::shared_ptr<const CsgTree> readCsgText(const std::string& text, const std::string& pathForMessages,
                                           Diagnostics& diags);

}  // namespace trazo
