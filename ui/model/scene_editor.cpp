// SceneEditor: the edits' bookkeeping; scene_edit and object_commands do the edits themselves.
#include "model/scene_editor.h"

#include <cstdio>

#include "model/camera_controller.h"

namespace trazo {

SceneEditor::SceneEditor(ViewerSession& session, const std::string& scenePath)
    : session_(session), scenePath_(scenePath), recovery_(scenePath) {}

void SceneEditor::commit(const Scene& before, const std::string& label, DirtyFlags changed, uint64_t gesture) {
    if (!changed) return;
    history_.commit(before, label, changed, gesture);
    objects_.selection = validSelection(session_.scene(), objects_.selection);
    selector_.invalidate();
    reportSelection();
}

void SceneEditor::cameraMoved(const Camera& before, const std::string& kind) {
    const auto now = Clock::now();
    if (kind != cameraKind_ || cameraGesture_ == 0 ||
        std::chrono::duration<double>(now - lastCamera_).count() > kCameraGestureSeconds)
        cameraGesture_ = beginGesture(objects_.gestures);
    cameraKind_ = kind;
    lastCamera_ = now;
    Scene previous = session_.scene();
    previous.camera = before;
    commit(previous, kind + " camera", kDirtyCamera, cameraGesture_);
}

DirtyFlags SceneEditor::undo() {
    if (move_.active()) return cancelMove();
    return historyStepped(history_.undo(session_.scene()));
}

DirtyFlags SceneEditor::redo() {
    if (move_.active()) return kDirtyNone;
    return historyStepped(history_.redo(session_.scene()));
}

DirtyFlags SceneEditor::historyStepped(DirtyFlags changed) {
    objects_.selection = validSelection(session_.scene(), objects_.selection);
    selector_.invalidate();
    reportSelection();
    cameraGesture_ = 0;
    return changed;
}

void SceneEditor::click(ImagePoint p) {
    selector_.click(session_, objects_.selection, p);
    objects_.scrollToSelection = true;
}

DirtyFlags SceneEditor::focusAt(ImagePoint p) {
    const std::optional<PickHit> hit = session_.pick(p.x, p.y);
    if (!hit) return kDirtyNone;
    Camera& camera = session_.scene().camera;
    const float distance = focalDistanceTo(camera, hit->point);
    if (!(distance > 0.0f) || distance == camera.focalDistance) return kDirtyNone;
    const Scene before = session_.scene();
    camera.focalDistance = distance;
    std::fprintf(stderr, "trazo: focus at %g on %s\n", double(distance),
                 selectionName(session_.scene(), hit->object).c_str());
    commit(before, "Focus camera", kDirtyCamera | kDirtyScene);
    cameraGesture_ = 0;  // the next navigation is a step of its own
    return kDirtyCamera | kDirtyScene;
}

void SceneEditor::clearSelection() {
    objects_.selection.reset();
    reportSelection();
}

DirtyFlags SceneEditor::duplicateSelected() {
    const Scene before = session_.scene();
    const ObjectEdit edit = trazo::duplicateSelected(session_.scene(), objects_.selection);
    commit(before, edit.label, edit.dirty);
    return edit.dirty;
}

DirtyFlags SceneEditor::deleteSelected() {
    const Scene before = session_.scene();
    const ObjectEdit edit = trazo::deleteSelected(session_.scene(), objects_.selection);
    commit(before, edit.label, edit.dirty);
    return edit.dirty;
}

DirtyFlags SceneEditor::addSphere(Vec3 at) {
    const Scene before = session_.scene();
    const ObjectEdit edit = addAndSelect(session_.scene(), objects_.selection, ObjectId::Kind::Sphere, at);
    commit(before, edit.label, edit.dirty);
    return edit.dirty;
}

bool SceneEditor::beginMove(ImagePoint cursor) {
    if (!objects_.selection || move_.active()) return false;
    return move_.begin(session_.scene(), *objects_.selection, cursor, session_.renderWidth(), session_.renderHeight());
}

bool SceneEditor::updateMove(ImagePoint cursor, float wheelNotches) {
    return move_.update(session_.scene(), cursor, wheelNotches);
}

DirtyFlags SceneEditor::confirmMove() {
    if (!move_.active()) return kDirtyNone;
    const ObjectId id = move_.object();
    const Vec3 d = move_.moved();
    const Scene before = move_.confirm();
    if (d.x == 0 && d.y == 0 && d.z == 0) return kDirtyNone;
    std::fprintf(stderr, "trazo: moved %s by (%g, %g, %g)\n", selectionName(session_.scene(), id).c_str(), d.x, d.y,
                 d.z);
    commit(before, "Move " + std::string(kindKeyword(id.kind)) + " " + std::to_string(id.index), kDirtyScene);
    return kDirtyScene;
}

DirtyFlags SceneEditor::cancelMove() {
    if (!move_.active()) return kDirtyNone;
    move_.cancel(session_.scene());
    selector_.invalidate();
    return kDirtyScene;
}

void SceneEditor::saved() {
    history_.markSaved();
    recovery_.update(session_.scene(), false);
}

void SceneEditor::opened(const std::string& path) {
    if (move_.active()) move_.confirm();  // the old scene's: dropped with it
    recovery_.update(session_.scene(), false);  // the old scene's file, if this session wrote it
    scenePath_ = path;
    recovery_ = RecoveryFile(path);
    history_.reset();
    objects_.selection.reset();
    cameraGesture_ = 0;
    selector_.invalidate();
    reportSelection();
}

bool SceneEditor::restoreRecovery(std::vector<std::string>& messages, DirtyFlags& changed) {
    Diagnostics diags;
    Scene recovered = RecoveryFile::read(scenePath_, diags);
    for (const Diagnostic& d : diags.items) messages.push_back(formatDiagnostic(d));
    if (diags.hasErrors()) return false;
    const Scene before = session_.scene();
    session_.scene() = std::move(recovered);
    changed = kDirtyScene | kDirtyCamera | kDirtySize;
    commit(before, "Restore recovered edits", changed);
    return true;
}

}  // namespace trazo
