// SceneFiles: save, open and quit with their questions; the scene itself changes through the session and the
// editor.
#include "view/scene_files.h"

#include <cstdio>
#include <utility>

#include "model/scene_opener.h"
#include "view/editor_dialogs.h"

namespace trazo {

SceneFiles::SceneFiles(const std::string& scenePath, bool offerRecovery, ViewerSession& session, SceneEditor& editor,
                       ExportController& exports, PanelState& state, Window& window)
    : scenePath_(scenePath), session_(session), editor_(editor), exports_(exports), state_(state), window_(window) {
    if (!offerRecovery) return;
    if (const auto found = RecoveryFile::find(scenePath_)) {
        recoveryPath_ = *found;
        askingRecovery_ = true;
    }
}

bool SceneFiles::closing() {
    if (!window_.shouldClose()) return false;
    if (quitConfirmed_ || !editor_.unsaved()) return true;
    window_.cancelClose();
    ask(Pending::Quit);
    return false;
}

bool SceneFiles::save() {
    if (!exports_.saveScene(session_.scene(), state_)) return false;
    editor_.saved();
    return true;
}

void SceneFiles::ask(Pending what, const std::string& path) {
    pending_ = what;
    pendingPath_ = path;
    askingUnsaved_ = true;
}

void SceneFiles::requestOpen(const std::string& path) {
    if (editor_.unsaved()) ask(Pending::Open, path);
    else openNow(path);
}

// Read as at start; on errors the messages go to the Open panel and stderr, and the scene stays.
void SceneFiles::openNow(const std::string& path) {
    OpenedScene opened = openSceneFile(path);
    for (const std::string& m : opened.messages) std::fprintf(stderr, "%s\n", m.c_str());
    if (opened.scene) {
        try {
            if (editor_.moving()) editor_.cancelMove();
            session_.replaceScene(std::move(*opened.scene));
        } catch (const std::exception& e) {  // the session keeps the old scene
            opened.messages = {path + ": " + e.what()};
            opened.scene.reset();
        }
    }
    if (!opened.scene) {
        std::fprintf(stderr, "trazo: cannot open %s; the current scene stays\n", path.c_str());
        state_.openMessages = std::move(opened.messages);
        return;
    }
    state_.openMessages.clear();
    scenePath_ = path;
    editor_.opened(path);
    exports_ = ExportController(path, "", state_);
    std::fprintf(stderr, "trazo: opened %s\n", path.c_str());
}

DirtyFlags SceneFiles::drawDialogs() {
    switch (drawQuitDialog(askingUnsaved_, state_.scenePath)) {
        case QuitAnswer::Save:
            if (save()) proceed();
            break;
        case QuitAnswer::Discard: proceed(); break;
        case QuitAnswer::Cancel: pending_ = Pending::None; break;
        case QuitAnswer::None: break;
    }
    DirtyFlags dirty = kDirtyNone;
    switch (drawRecoveryDialog(askingRecovery_, recoveryPath_)) {
        case RecoveryAnswer::Restore:
            if (!editor_.restoreRecovery(state_.openMessages, dirty)) dirty = kDirtyNone;
            break;
        case RecoveryAnswer::Discard: editor_.discardRecovery(); break;
        case RecoveryAnswer::Keep:
        case RecoveryAnswer::None: break;
    }
    return dirty;
}

void SceneFiles::proceed() {
    const Pending what = std::exchange(pending_, Pending::None);
    if (what == Pending::Quit) {
        quitConfirmed_ = true;
        window_.requestClose();
    } else if (what == Pending::Open) {
        openNow(pendingPath_);
    }
}

}  // namespace trazo
