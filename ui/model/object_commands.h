// What the Objects panel's buttons and the viewer's object keys do (host, no ImGui): each edits the scene,
// keeps the selection pointing at the right object, and says what changed and how to label the undo step.
#pragma once

#include <optional>
#include <string>

#include "model/dirty_flags.h"
#include "model/scene_edit.h"
#include "scene/diagnostic.h"

namespace trazo {

using Selection = std::optional<ObjectId>;

// One edit's outcome: what to redo in the viewer and the undo step's label ("" and kDirtyNone: nothing).
struct ObjectEdit {
    DirtyFlags dirty = kDirtyNone;
    std::string label;
};

// The selection if it still names an object of `scene` (after an undo removed it, say), else none.
Selection validSelection(const Scene& scene, Selection selection);

// Adds a primitive or light at `at`, newObjectSize(scene.camera) across, and selects it ("Add Sphere 3").
ObjectEdit addAndSelect(Scene& scene, Selection& selection, ObjectId::Kind kind, Vec3 at);
// Adds a Mesh or CSG from `path` at `at` and selects it; on failure the scene and selection stay and
// `diags` says why.
ObjectEdit addFileAndSelect(Scene& scene, Selection& selection, ObjectId::Kind kind, const std::string& path,
                            Vec3 at, Diagnostics& diags);
// Duplicates the selected object in place and selects the copy ("Duplicate Sphere 2").
ObjectEdit duplicateSelected(Scene& scene, Selection& selection);
// Deletes the selected object and selects its neighbour (deleteObject) ("Delete Sphere 2").
ObjectEdit deleteSelected(Scene& scene, Selection& selection);
// Moves the selected object by a world delta ("Move Sphere 2"); the viewer's drag commits each frame's
// move with one gesture id.
ObjectEdit moveSelected(Scene& scene, Selection selection, Vec3 delta);

}  // namespace trazo
