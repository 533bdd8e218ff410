// placeMeshes(): every Mesh block of a scene into the arrays, each either built (its BVH) or reused from an
// earlier flatten. Host code, called by flatten().
#pragma once

#include "flatten/flatten.h"

namespace trazo {

// Appends the meshes in Scene order to out.meshes, meshNodes, triangles and triangleCorners (which must be
// empty) and fills result.meshes, meshesBuilt, meshesReused and reused; see flatten()'s `previous`.
void placeMeshes(const Scene& scene, FlattenResult* previous, FlattenResult& result);

}  // namespace trazo
