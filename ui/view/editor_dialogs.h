// The viewer's questions (ImGui modals): quitting with unsaved edits, and a recovery file found at start.
// Each is asked while its flag is set; the answer comes back once, and the flag is then cleared.
#pragma once

#include <string>

namespace trazo {

enum class QuitAnswer { None, Save, Discard, Cancel };
// "Save changes to SCENE before quitting?" Save / Discard / Cancel (Escape cancels).
QuitAnswer drawQuitDialog(bool& asking, const std::string& savePath);

enum class RecoveryAnswer { None, Restore, Discard, Keep };
// "Unsaved edits of SCENE were kept in RECOVERY": Restore them / Discard (remove the file) / Keep it for later.
RecoveryAnswer drawRecoveryDialog(bool& asking, const std::string& recoveryPath);

}  // namespace trazo
