// SceneEditor: every edit of the viewer's scene passes through it (the panels', the camera's navigation,
// moves by hand, add / duplicate / delete, undo and redo, a recovered scene, another scene opened), so that
// each is one undo step (EditHistory), the recovery file follows the unsaved state (RecoveryFile), and the
// selection stays valid and logged (SelectionController). It returns what changed; the frame loop marks the
// session dirty. No GL and no ImGui.
//
// The camera counts as an edit: it is saved with the scene, so navigating marks the scene unsaved and is one
// undo step per gesture (a drag, a run of wheel notches or fly keys, F, R); undoing an object edit never moves
// the camera (EditHistory restores it only for steps that changed it).
#pragma once

#include <chrono>
#include <string>

#include "model/edit_history.h"
#include "model/move_gesture.h"
#include "model/panel_state.h"
#include "model/recovery_file.h"
#include "model/selection_controller.h"
#include "model/viewer_session.h"

namespace trazo {

class SceneEditor {
public:
    using Clock = std::chrono::steady_clock;
    // Camera changes closer together than this make one undo step.
    static constexpr double kCameraGestureSeconds = 0.5;

    SceneEditor(ViewerSession& session, const std::string& scenePath);

    ObjectsPanelState& objects() { return objects_; }  // the Objects panel's state: selection, gesture ids
    const Selection& selection() const { return objects_.selection; }
    const EditHistory& history() const { return history_; }
    bool unsaved() const { return history_.unsaved(); }

    // An edit already made to the session's scene: `before` is the scene as it was.
    void commit(const Scene& before, const std::string& label, DirtyFlags changed, uint64_t gesture = 0);
    // The camera was navigated from `before` (kind: "Orbit", "Pan", "Dolly", "Fly", ...).
    void cameraMoved(const Camera& before, const std::string& kind);
    DirtyFlags undo();
    DirtyFlags redo();

    // Selection. A click at `p` (full-size image pixels) picks; the others act on the selection.
    void click(ImagePoint p);
    // "Focus here": the camera's FocalDistance becomes the along-view distance (focalDistanceTo) of the surface
    // the camera ray through `p` hits first, as one undo step (kDirtyCamera | kDirtyScene: the lens is fixed at
    // flatten). The background, or a distance equal to the current one, changes nothing (kDirtyNone).
    DirtyFlags focusAt(ImagePoint p);
    void clearSelection();
    DirtyFlags duplicateSelected();
    DirtyFlags deleteSelected();
    DirtyFlags addSphere(Vec3 at);

    // A move of the selection by hand (move_gesture.h): begin with the cursor where it is, update as it moves
    // (true when the scene changed), then confirm (one undo step) or cancel (the scene as it was).
    bool beginMove(ImagePoint cursor);
    bool moving() const { return move_.active(); }
    bool updateMove(ImagePoint cursor, float wheelNotches);
    DirtyFlags confirmMove();
    DirtyFlags cancelMove();

    // The scene was saved (history's saved point; the recovery file goes).
    void saved();
    // The session's scene was replaced by the file at `path`: history, selection, recovery file start over.
    void opened(const std::string& path);
    // Puts the recovery file's scene in place of the current one, as one undo step; false (and the reasons in
    // `messages`) when it does not read.
    bool restoreRecovery(std::vector<std::string>& messages, DirtyFlags& changed);
    void discardRecovery() { recovery_.remove(); }
    // Call every frame: writes the recovery file while there are unsaved edits (at most once a second).
    void tick() { recovery_.update(session_.scene(), history_.unsaved()); }
    // A quit without unsaved edits, or with edits the user discarded: the recovery file goes.
    void quitting() { recovery_.remove(); }

    // The outline of the selection for the display (SelectionController::refreshOutline).
    void invalidateOutline() { selector_.invalidate(); }
    bool refreshOutline(std::vector<uint8_t>& outline) {
        return selector_.refreshOutline(session_, objects_.selection, outline);
    }
    // Logs a selection changed by the Objects panel or an edit.
    void reportSelection() { selector_.report(session_.scene(), objects_.selection); }

private:
    // After an undo or redo: the selection kept valid and its outline redrawn, the camera's gesture ended.
    DirtyFlags historyStepped(DirtyFlags changed);

    ViewerSession& session_;
    std::string scenePath_;
    EditHistory history_;
    RecoveryFile recovery_;
    ObjectsPanelState objects_;
    SelectionController selector_;
    MoveGesture move_;
    std::string cameraKind_;
    uint64_t cameraGesture_ = 0;
    Clock::time_point lastCamera_{};
};

}  // namespace trazo
