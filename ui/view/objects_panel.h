// The viewer's Objects panel (ImGui): every object and light of the scene in a list, the selected one's
// parameters (its block table's rows), material and transform steps editable, and buttons that add,
// duplicate and delete. Like panels.h: a free function over the scene and a small state, no static state, no
// backend; it returns what changed, and the frame loop re-uploads and commits it to the edit history.
#pragma once

#include <string>

#include "model/dirty_flags.h"
#include "model/object_commands.h"
#include "model/panel_state.h"
#include "scene/scene.h"
#include "view/param_editor.h"

namespace trazo {

struct ObjectsPanelActions {
    std::string label;       // the undo step's name when something changed ("Edit Sphere 2", "Add Box 3")
    uint64_t gesture = 0;    // non-zero while a widget is held: the frames of one drag commit as one step
    bool selectionChanged = false;
    // The one object whose parameters, material or transforms changed (what an incremental re-upload needs);
    // none when objects were added or deleted (the arrays change length) or nothing changed.
    Selection changedObject;
};

// The whole panel (draw it inside a window or a collapsing header). `viewCentre` is where new objects go
// (the point the camera looks at, or the centre of the view at the selection's depth).
DirtyFlags drawObjectsPanel(Scene& scene, ObjectsPanelState& state, ObjectsPanelActions& actions, Vec3 viewCentre);

// Its parts: the list, the add buttons, the selected object's editor.
void drawObjectList(const Scene& scene, ObjectsPanelState& state, ObjectsPanelActions& actions);
DirtyFlags drawAddButtons(Scene& scene, ObjectsPanelState& state, ObjectsPanelActions& actions, Vec3 viewCentre);
DirtyFlags drawObjectEditor(Scene& scene, ObjectsPanelState& state, ObjectsPanelActions& actions);
// The steps of a Box, Mesh or CSG: kind, values, order; a change the reader would refuse is not made
// (transformProblem's reason goes to `status`).
DirtyFlags drawTransformSteps(std::vector<TransformStep>& steps, ObjectId::Kind kind, Gestures& gestures,
                              std::string& status, const MeshData* mesh = nullptr);

}  // namespace trazo
