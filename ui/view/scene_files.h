// SceneFiles: the viewer's scene file and the questions around it: saving (the Export panel's name), opening
// another scene at run time (scene_opener.h; errors to the Open panel), quitting, each of the last two asked
// about first when there are unsaved edits (Save / Discard / Cancel), and the recovery file an earlier session
// left, offered at start (editor_dialogs.h).
#pragma once

#include <string>

#include "model/export_controller.h"
#include "model/scene_editor.h"
#include "model/viewer_session.h"
#include "view/panels.h"
#include "view/window.h"

namespace trazo {

class SceneFiles {
public:
    // `offerRecovery`: ask about SCENE.recovery when there is one (not in automation, which leaves files alone).
    SceneFiles(const std::string& scenePath, bool offerRecovery, ViewerSession& session, SceneEditor& editor,
               ExportController& exports, PanelState& state, Window& window);

    const std::string& scenePath() const { return scenePath_; }
    // Whether the loop may end: the close button or Ctrl+Q is vetoed while there are unsaved edits, until the
    // question is answered.
    bool closing();
    bool save();  // writes the scene under the Export panel's name; the history's saved point on success
    void requestOpen(const std::string& path);
    // The questions (ImGui), inside the frame; what a restored recovery file changed (kDirtyNone: nothing).
    DirtyFlags drawDialogs();

private:
    enum class Pending { None, Quit, Open };
    void ask(Pending what, const std::string& path = "");
    void openNow(const std::string& path);
    void proceed();  // what waited for the unsaved-edits question

    std::string scenePath_;
    ViewerSession& session_;
    SceneEditor& editor_;
    ExportController& exports_;
    PanelState& state_;
    Window& window_;
    bool askingUnsaved_ = false, askingRecovery_ = false, quitConfirmed_ = false;
    Pending pending_ = Pending::None;
    std::string pendingPath_, recoveryPath_;
};

}  // namespace trazo
