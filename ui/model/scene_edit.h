// Edits of the host scene's objects and lights (host, no UI): list and name them, add, duplicate, delete and
// move them, and edit Box/Mesh/CSG transform lists. Pure functions over a Scene; the viewer's Objects panel
// and its drag-to-move call them, and the edit history snapshots the scene around them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/aabb.h"
#include "scene/diagnostic.h"
#include "scene/object_id.h"
#include "scene/scene.h"

namespace trazo {

constexpr int kObjectIdKindCount = int(ObjectId::kKindCount);

// The kind's block keyword ("Sphere", "CSG", "PointLight", ...).
const char* kindKeyword(ObjectId::Kind kind);
// How many objects of `kind` the scene holds.
size_t objectCount(const Scene& scene, ObjectId::Kind kind);
bool isValidObject(const Scene& scene, ObjectId id);

// Every object, then every light: kinds in ObjectId::Kind order, file order within a kind.
std::vector<ObjectId> listObjects(const Scene& scene);
// A display name: kind, index, and the material's name or the file's ("Sphere 2 (red)", "Mesh 0 (bunny.obj,
// white)", "Point light 1"); "(default)" for an object on the default material.
std::string describeObject(const Scene& scene, ObjectId id);
// The block's place in the scene file; an empty file name when the object was added in the viewer.
const SourceLocation& objectWhere(const Scene& scene, ObjectId id);

// The material index of an object (kDefaultMaterial for lights, which have none); set ignores lights.
int32_t objectMaterial(const Scene& scene, ObjectId id);
void setObjectMaterial(Scene& scene, ObjectId id, int32_t material);
// The transform list of a Box, Mesh or CSG object; null for the kinds without one.
std::vector<TransformStep>* objectTransforms(Scene& scene, ObjectId id);

// World bounds: a sphere's and a cylinder's exact boxes (as the renderer's), a box's transformed unit cube,
// a mesh's or CSG solid's object-space box with its 8 corners transformed (the reader's measure; looser than
// the tight box under a rotation), an area light's rectangle, a point light's point. Empty for a CSG solid
// that is empty everywhere or a mesh or CSG whose file did not load. Linear in a mesh's vertices.
Aabb objectWorldBounds(const Scene& scene, ObjectId id);
// The point to drag an object by: the centre of its bounds (a light's position).
Vec3 objectAnchor(const Scene& scene, ObjectId id);

// The size of a new object: a fifth of the height the camera sees at its point of interest.
float newObjectSize(const Camera& camera);

// A new Sphere, Box, Cylinder, PointLight or AreaLight centred at `at`, `size` across (sphere diameter, box
// edge, cylinder height and diameter, area light side), on the default material, appended to its kind. A
// cylinder stands on +Y; an area light faces down (−Y), white; a point light is white. A Mesh or CSG is read
// from a file (addObjectFromFile): for those nothing is added and the id returned is not a valid one.
ObjectId addObject(Scene& scene, ObjectId::Kind kind, Vec3 at, float size = 1.0f);
// A new Mesh (an .obj) or CSG (a .csg) read from `path` (relative paths from the scene's folder), placed by
// one Translation so that the centre of its bounds is at `at`, in the file's own units. A file another
// object of the scene already uses is shared, not read again. Null after putting the problems in `diags`
// (the reader's FILE:LINE messages); the scene is then unchanged.
std::optional<ObjectId> addObjectFromFile(Scene& scene, ObjectId::Kind kind, const std::string& path, Vec3 at,
                                          Diagnostics& diags);
// Replaces a Mesh's or CSG's file (its Source) with `path`, read as addObjectFromFile reads it; its
// transforms and material stay. False, with the scene unchanged, after putting the problems in `diags`.
bool replaceObjectSource(Scene& scene, ObjectId id, const std::string& path, Diagnostics& diags);

// Appends a copy of the object to its kind, moved by `offset` (translateObject; zero: in place, the copy on
// top of the original, ready to be dragged away). The copy has no source line. Returns the copy's id.
ObjectId duplicateObject(Scene& scene, ObjectId id, Vec3 offset = Vec3(0, 0, 0));
// Removes the object. Later objects of the same kind move down one index (idAfterDelete); other kinds keep
// theirs. Returns what to select next: the object now at the same index, else the previous one of the same
// kind, else none.
std::optional<ObjectId> deleteObject(Scene& scene, ObjectId id);
// What `id` names after `deleted` was removed: none when it was the deleted one, one index lower when it was
// a later object of the same kind, otherwise itself.
std::optional<ObjectId> idAfterDelete(ObjectId deleted, ObjectId id);

// Moves the object by `delta` in world space: a sphere's centre, a cylinder's base, a light's position; for a
// Box, Mesh or CSG the trailing Translation step (appended when the list does not end with one, removed when
// it becomes exactly zero), so a drag's many moves never lengthen the list.
void translateObject(Scene& scene, ObjectId id, Vec3 delta);

// Transform list edits for the panel. A new step is the identity of its kind (Translation 0 0 0, Rotation
// about +Y by 0, Scale 1 1 1), inserted at `at` (clamped to the end).
void insertTransformStep(std::vector<TransformStep>& steps, size_t at, TransformStep::Kind kind);
// Swaps step i with its neighbour (direction −1: earlier, +1: later); false when there is none.
bool moveTransformStep(std::vector<TransformStep>& steps, size_t i, int direction);
// Why the reader would refuse the composed list, in words ("" when it would not): a map single precision
// cannot hold or invert; for a Box, face normals that leave single precision; for a Mesh whose `mesh` is
// given, a span past 1e9 (the reader's limits, docs/LIMITS.md).
std::string transformProblem(const std::vector<TransformStep>& steps, ObjectId::Kind kind,
                             const MeshData* mesh = nullptr);

}  // namespace trazo
