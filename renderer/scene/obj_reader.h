// OBJ reader (host): Wavefront OBJ → MeshData (SPEC §3 Mesh), with OBJFILE:LINE errors for malformed files.
#pragma once

#include <memory>
#include <string>

#include "scene/diagnostic.h"
#include "scene/scene.h"

namespace trazo {

// Reads `v`, `vt`, `vn` and `f` (1-based or negative indices; polygons fan-triangulated as (0, k, k+1));
// `g`, `o`, `s`, `usemtl`, `mtllib`, `l`, `p` are accepted and ignored (no .mtl is read).
// hasNormals / hasUvs are true only when every corner has one; otherwise every corner's index is -1 and
// the renderer computes smooth normals / ignores textures. Returns null after reporting any problem.
std::shared_ptr<const MeshData> readObjFile(const std::string& path, Diagnostics& diags);

// Same, from text already read; `pathForMessages` names the file in diagnostics.
std::shared_ptr<const MeshData> readObjText(const std::string& text, const std::string& pathForMessages,
                                            Diagnostics& diags);

}  // namespace trazo
