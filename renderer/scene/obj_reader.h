// OBJ reader (host): Wavefront OBJ → MeshData (SPEC §3 Mesh), with OBJFILE:LINE errors for malformed files.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "scene/diagnostic.h"
#include "scene/scene.h"

namespace trazo {

// The most one OBJ file may hold, each counted on its own: vertices (`v`), normals (`vn`), texture
// coordinates (`vt`), and triangles after fan triangulation. Past any of them the file is refused at the
// line that crosses it, before the data is stored (2^26 triangles take about 10 GB once flattened).
inline constexpr size_t kMaxObjElements = size_t(1) << 26;
inline constexpr size_t kMaxObjTriangles = size_t(1) << 26;
// The longest line the reader takes (about 100 000 polygon vertices): tinyobjloader holds a line, and a
// face's indices, in memory at once.
inline constexpr size_t kMaxObjLineBytes = size_t(1) << 20;

// ---------------------------------------------------------------------------------------------------------
// What a MeshData from readObjFile / readObjText guarantees (the OBJ mesh contract). Code that indexes a
// MeshData (flatten/flatten_mesh.cpp: prepareMesh, appendMesh) relies on this and on nothing else:
//
//  1. Counts: corners.size() is a multiple of 3, at least 3 and at most 3 · kMaxObjTriangles (so triangle
//     and corner numbers fit a uint32_t); positions.size() and normals.size() are at most kMaxObjElements;
//     uvs.size() is even and uvs.size() / 2 is at most kMaxObjElements (so every index, and 2 · uv + 1,
//     fits an int32_t).
//  2. Indices: every corner's position is in [0, positions.size()). When hasNormals, every corner's normal
//     is in [0, normals.size()); otherwise every corner's normal is -1. When hasUvs, every corner's uv is
//     in [0, uvs.size() / 2); otherwise every corner's uv is -1. (An attribute given on some corners only
//     counts as absent: hasNormals / hasUvs are true only when every corner has one.)
//  3. Values: every component of positions, normals and uvs is a finite float (normals may be zero or of
//     any length; degenerate triangles may occur).
//
// The reader enforces it in one place, on the data tinyobjloader actually produced (after its negative
// indices are resolved), not on a reading of the text of its own; the line check beside it only gives
// better messages for what tinyobjloader reads silently as 0 (bad numbers, trailing text, huge indices).
// Lines end at \n, \r\n or a lone \r, as tinyobjloader reads them; reported line numbers count them so.
// ---------------------------------------------------------------------------------------------------------

// The first way `mesh` breaks the contract above, in words ("corner 7: normal index 9 is out of range (the
// mesh has 3)"); empty when it keeps it. Linear in the mesh's size: for checks and debug asserts.
std::string objMeshContractViolation(const MeshData& mesh);

// Reads `v`, `vt`, `vn` and `f` (1-based or negative indices; polygons fan-triangulated as (0, k, k+1));
// `g`, `o`, `s`, `usemtl`, `mtllib`, `l`, `p` are accepted and ignored (no .mtl is read).
// hasNormals / hasUvs are true only when every corner has one; otherwise every corner's index is -1 and
// the renderer computes smooth normals / ignores textures. Returns null after reporting any problem as
// OBJFILE:LINE[:COLUMN]; otherwise the mesh keeps the contract above.
std::shared_ptr<const MeshData> readObjFile(const std::string& path, Diagnostics& diags);

// Same, from text already read; `pathForMessages` names the file in diagnostics.
std::shared_ptr<const MeshData> readObjText(const std::string& text, const std::string& pathForMessages,
                                            Diagnostics& diags);

}  // namespace trazo
