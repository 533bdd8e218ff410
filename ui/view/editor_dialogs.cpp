// The modals: opened the frame their flag is first seen, answered by a button.
#include "view/editor_dialogs.h"

#include <imgui.h>

namespace trazo {
namespace {

// Opens the popup `name` while `asking` and centres it; true while it is open.
bool beginQuestion(const char* name, bool asking) {
    if (asking && !ImGui::IsPopupOpen(name)) ImGui::OpenPopup(name);
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0.5f * io.DisplaySize.x, 0.5f * io.DisplaySize.y), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    return ImGui::BeginPopupModal(name, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
}

// The modal `name` while `asking`: two lines of text and three buttons on one line, Escape also pressing the last.
// A press answers and closes it (asking = false); `none` until then.
template <class Answer>
Answer ask(const char* name, bool& asking, const std::string (&lines)[2], const char* const (&labels)[3],
           const Answer (&answers)[3], Answer none) {
    if (!beginQuestion(name, asking)) return none;
    for (const std::string& line : lines) ImGui::TextUnformatted(line.c_str());
    Answer answer = none;
    for (int i = 0; i < 3; ++i) {
        if (i > 0) ImGui::SameLine();
        if (ImGui::Button(labels[i]) || (i == 2 && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))))
            answer = answers[i];
    }
    if (answer != none) {
        asking = false;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
    return answer;
}

}  // namespace

QuitAnswer drawQuitDialog(bool& asking, const std::string& savePath) {
    return ask("Unsaved changes", asking,
               {"The scene has unsaved edits.", "Save them to " + savePath + " before quitting?"},
               {"Save", "Discard", "Cancel"}, {QuitAnswer::Save, QuitAnswer::Discard, QuitAnswer::Cancel},
               QuitAnswer::None);
}

RecoveryAnswer drawRecoveryDialog(bool& asking, const std::string& recoveryPath) {
    return ask("Recovered edits", asking, {"An earlier session left unsaved edits of this scene in", recoveryPath},
               {"Restore them", "Discard them", "Not now"},
               {RecoveryAnswer::Restore, RecoveryAnswer::Discard, RecoveryAnswer::Keep}, RecoveryAnswer::None);
}

}  // namespace trazo
