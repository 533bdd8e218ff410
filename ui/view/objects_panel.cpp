// The Objects panel in ImGui: scene_edit and object_commands do the edits; this file only draws and routes.
#include "view/objects_panel.h"

#include <imgui.h>

#include <algorithm>

#include "scene/block_table.h"

namespace trazo {
namespace {

using Kind = ObjectId::Kind;
using Step = TransformStep::Kind;

void finish(ObjectsPanelActions& actions, const ObjectEdit& edit, DirtyFlags& dirty) {
    if (!edit.dirty) return;
    dirty |= edit.dirty;
    actions.label = edit.label;
    actions.gesture = 0;
    actions.selectionChanged = true;
}

// The first errors of `diags`, one a line, for the status line.
std::string errorsOf(const Diagnostics& diags) {
    std::string s;
    int shown = 0;
    for (const Diagnostic& d : diags.items) {
        if (d.severity != Severity::Error || ++shown > 4) continue;
        if (!s.empty()) s += '\n';
        s += formatDiagnostic(d);
    }
    return s;
}

// The rows of object `index` of `objects` (its kind's table, acting on the reader's draft).
template <class T>
DirtyFlags editObject(std::vector<T>& objects, uint32_t index, Gestures& gestures) {
    ObjectDraft<T> draft{objects[index], {}, {}};
    const DirtyFlags dirty = editRows(objectTable<T>(), draft, kDirtyScene, &gestures);
    if (dirty) objects[index] = std::move(draft.object);
    return dirty;
}

DirtyFlags editRowsOf(Scene& scene, ObjectId id, Gestures& gestures) {
    switch (id.kind) {
#define TRAZO_X(Shape, array, HostKind, keyword) \
    case Kind::HostKind: return editObject(scene.array, id.index, gestures);
        TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
#define TRAZO_X(Data, array, HostKind, ...) \
    case Kind::HostKind: return editRows(lightTable<HostKind>(), scene.array[id.index], kDirtyScene, &gestures);
        TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    }
    TRAZO_UNREACHABLE();
}

// The transform rows' parameter info (name, checks) for a step kind.
const ParamInfo& stepInfo(Step kind) {
    const char* name = kind == Step::Translation ? "Translation" : kind == Step::Rotation ? "Rotation" : "Scale";
    for (const ParamSpec<ObjectDraft<Box>>& row : objectTable<Box>())
        if (row.info.accumulates && row.info.name == name) return row.info;
    return objectTable<Box>().front().info;  // not reached: the Box table has all three
}

// One step's kind and values; true when `step` was changed (and passes the row's checks).
bool drawStep(TransformStep& step, Gestures& gestures) {
    bool changed = false;
    int kind = int(step.kind);
    ImGui::SetNextItemWidth(100);
    if (ImGui::Combo("##kind", &kind, "Translation\0Rotation\0Scale\0") && kind != int(step.kind)) {
        std::vector<TransformStep> fresh;  // another kind starts as its identity
        insertTransformStep(fresh, 0, Step(kind));
        step = fresh[0];
        changed = true;
    }
    trackGesture(gestures, changed);
    ImGui::SameLine();
    ParamValue v;
    v.numbers = {step.value.x, step.value.y, step.value.z, step.angle};
    float f[3] = {step.value.x, step.value.y, step.value.z};
    float angle = step.angle;
    const float width = ImGui::CalcItemWidth();
    ImGui::SetNextItemWidth(step.kind == Step::Rotation ? width * 0.7f : width);
    bool edited = ImGui::DragFloat3(step.kind == Step::Rotation ? "##axis" : "##value", f, 0.01f);
    if (step.kind == Step::Rotation) {
        trackGesture(gestures, edited);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(width * 0.3f);
        const bool turned = ImGui::DragFloat("##angle", &angle, 0.005f, 0.0f, 0.0f, "%.3f rad");
        edited |= turned;
        trackGesture(gestures, turned);
    } else {
        trackGesture(gestures, edited);
    }
    if (edited) {
        ParamValue edit = v;
        edit.numbers = {f[0], f[1], f[2], angle};
        if (fitToCheck(stepInfo(step.kind), edit) && edit.numbers != v.numbers) {
            step.value = edit.vec3();
            step.angle = edit.real(3);
            changed = true;
        }
    }
    return changed;
}

}  // namespace

DirtyFlags drawTransformSteps(std::vector<TransformStep>& steps, ObjectId::Kind kind, Gestures& gestures,
                              std::string& status, const MeshData* mesh) {
    std::vector<TransformStep> edited = steps;
    bool changed = false;
    for (size_t i = 0; i < edited.size(); ++i) {
        ImGui::PushID(int(i));
        changed |= drawStep(edited[i], gestures);
        ImGui::SameLine();
        if (ImGui::SmallButton("^")) changed |= moveTransformStep(edited, i, -1);
        ImGui::SameLine();
        if (ImGui::SmallButton("v")) changed |= moveTransformStep(edited, i, +1);
        ImGui::SameLine();
        if (ImGui::SmallButton("x")) {
            edited.erase(edited.begin() + std::ptrdiff_t(i));
            changed = true;
            ImGui::PopID();
            break;  // the list changed under the loop; the rest draws next frame
        }
        ImGui::PopID();
    }
    ImGui::TextDisabled("Add step:");
    for (const auto& [label, kindToAdd] : {std::pair{"Translation", Step::Translation}, std::pair{"Rotation", Step::Rotation},
                                           std::pair{"Scale", Step::Scale}}) {
        ImGui::SameLine();
        if (ImGui::SmallButton(label)) {
            insertTransformStep(edited, edited.size(), kindToAdd);
            changed = true;
        }
    }
    if (!changed) return kDirtyNone;
    const std::string problem = transformProblem(edited, kind, mesh);
    if (!problem.empty()) {
        status = problem + "; the change was not made";
        return kDirtyNone;
    }
    steps = std::move(edited);
    return kDirtyScene;
}

void drawObjectList(const Scene& scene, ObjectsPanelState& state, ObjectsPanelActions& actions) {
    const float row = ImGui::GetTextLineHeightWithSpacing();
    if (!ImGui::BeginChild("object list", ImVec2(0, 8.5f * row), true)) {
        ImGui::EndChild();
        return;
    }
    const std::vector<ObjectId> ids = listObjects(scene);
    if (state.scrollToSelection && state.selection) {  // rows off screen are not drawn (the clipper): scroll by index
        const auto at = std::find(ids.begin(), ids.end(), *state.selection);
        ImGui::SetScrollY(float(at - ids.begin()) * row - 0.5f * ImGui::GetWindowHeight() + row);
    }
    state.scrollToSelection = false;
    ImGuiListClipper clipper;
    clipper.Begin(int(ids.size()), row);
    while (clipper.Step()) {
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            const ObjectId id = ids[size_t(i)];
            ImGui::PushID(i);
            const bool selected = state.selection == id;
            if (ImGui::Selectable(describeObject(scene, id).c_str(), selected) && !selected) {
                state.selection = id;
                actions.selectionChanged = true;
            }
            const SourceLocation& where = objectWhere(scene, id);
            if (!where.file.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s:%d", where.file.c_str(), where.line);
            ImGui::PopID();
        }
    }
    ImGui::EndChild();
}

DirtyFlags drawAddButtons(Scene& scene, ObjectsPanelState& state, ObjectsPanelActions& actions, Vec3 viewCentre) {
    DirtyFlags dirty = kDirtyNone;
    ImGui::TextDisabled("Add at the view centre:");
    // Every kind the list (objects/object_kind_list.h) makes in place, then the lights; the kinds read from a
    // file below, from the path typed.
    std::vector<std::pair<const char*, Kind>> inPlace, fromFile;
#define TRAZO_X(Shape, array, HostKind, keyword) \
    (HostKind::kReadFromFile ? fromFile : inPlace).push_back({keyword, Kind::HostKind});
    TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
#define TRAZO_X(Data, array, HostKind, keyword, label, ...) inPlace.push_back({label, Kind::HostKind});
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    for (size_t i = 0; i < inPlace.size(); ++i) {
        if (i > 0) ImGui::SameLine();
        if (ImGui::SmallButton(inPlace[i].first))
            finish(actions, addAndSelect(scene, state.selection, inPlace[i].second, viewCentre), dirty);
    }
    ImGui::InputText("File", state.filePath, sizeof state.filePath);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("an .obj or .csg file; a relative path starts at the scene's folder");
    for (size_t i = 0; i < fromFile.size(); ++i) {
        if (i > 0) ImGui::SameLine();
        if (!ImGui::SmallButton((std::string("Add ") + fromFile[i].first).c_str())) continue;
        Diagnostics diags;
        const ObjectEdit edit =
            addFileAndSelect(scene, state.selection, fromFile[i].second, state.filePath, viewCentre, diags);
        state.status = errorsOf(diags);
        finish(actions, edit, dirty);
    }
    return dirty;
}

DirtyFlags drawObjectEditor(Scene& scene, ObjectsPanelState& state, ObjectsPanelActions& actions) {
    if (!state.selection) {
        ImGui::TextDisabled("Click an object in the image or the list.");
        return kDirtyNone;
    }
    const ObjectId id = *state.selection;
    DirtyFlags dirty = kDirtyNone;
    ImGui::Text("%s", describeObject(scene, id).c_str());
    const SourceLocation& where = objectWhere(scene, id);
    if (!where.file.empty()) {
        ImGui::SameLine();
        ImGui::TextDisabled("line %d", where.line);
    }
    if (ImGui::SmallButton("Duplicate")) finish(actions, duplicateSelected(scene, state.selection), dirty);
    ImGui::SameLine();
    if (ImGui::SmallButton("Delete")) finish(actions, deleteSelected(scene, state.selection), dirty);
    if (dirty) return dirty;  // the selection moved: its editor draws next frame

    const std::string editLabel = "Edit " + std::string(kindKeyword(id.kind)) + " " + std::to_string(id.index);
    DirtyFlags edits = kDirtyNone;
    if (!id.isLight()) {
        std::vector<std::string> names;
        for (const Material& m : scene.materials) names.push_back(m.name);
        int32_t material = objectMaterial(scene, id);
        if (comboIndex("Material", material, names, "(default)")) {
            setObjectMaterial(scene, id, material);
            edits |= kDirtyScene;
        }
    }
    edits |= editRowsOf(scene, id, state.gestures);
    if (id.kind == Kind::Mesh || id.kind == Kind::Csg) {
        const std::string& source = id.kind == Kind::Mesh ? scene.meshes[id.index].source : scene.csgs[id.index].source;
        ImGui::TextWrapped("Source: %s", source.c_str());
        if (ImGui::SmallButton("Read Source from File")) {
            Diagnostics diags;
            if (replaceObjectSource(scene, id, state.filePath, diags)) edits |= kDirtyScene;
            state.status = errorsOf(diags);
        }
    }
    if (std::vector<TransformStep>* steps = objectTransforms(scene, id)) {
        ImGui::PushID("steps");
        ImGui::TextDisabled("Transforms, applied in this order:");
        const MeshData* mesh = id.kind == Kind::Mesh ? scene.meshes[id.index].data.get() : nullptr;
        edits |= drawTransformSteps(*steps, id.kind, state.gestures, state.status, mesh);
        ImGui::PopID();
    }
    if (edits) {
        actions.label = editLabel;
        actions.gesture = state.gestures.edited;
        actions.changedObject = id;
    }
    return dirty | edits;
}

DirtyFlags drawObjectsPanel(Scene& scene, ObjectsPanelState& state, ObjectsPanelActions& actions, Vec3 viewCentre) {
    startGestures(state.gestures);
    state.selection = validSelection(scene, state.selection);
    drawObjectList(scene, state, actions);
    DirtyFlags dirty = drawAddButtons(scene, state, actions, viewCentre);
    ImGui::Separator();
    ImGui::PushID("selected");
    if (!dirty) dirty |= drawObjectEditor(scene, state, actions);
    ImGui::PopID();
    if (!state.status.empty()) ImGui::TextWrapped("%s", state.status.c_str());
    return dirty;
}

}  // namespace trazo
