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

}  // namespace

QuitAnswer drawQuitDialog(bool& asking, const std::string& savePath) {
    QuitAnswer answer = QuitAnswer::None;
    if (!beginQuestion("Unsaved changes", asking)) return answer;
    ImGui::Text("The scene has unsaved edits.");
    ImGui::Text("Save them to %s before quitting?", savePath.c_str());
    if (ImGui::Button("Save")) answer = QuitAnswer::Save;
    ImGui::SameLine();
    if (ImGui::Button("Discard")) answer = QuitAnswer::Discard;
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) answer = QuitAnswer::Cancel;
    if (answer != QuitAnswer::None) {
        asking = false;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
    return answer;
}

RecoveryAnswer drawRecoveryDialog(bool& asking, const std::string& recoveryPath) {
    RecoveryAnswer answer = RecoveryAnswer::None;
    if (!beginQuestion("Recovered edits", asking)) return answer;
    ImGui::Text("An earlier session left unsaved edits of this scene in");
    ImGui::Text("%s", recoveryPath.c_str());
    if (ImGui::Button("Restore them")) answer = RecoveryAnswer::Restore;
    ImGui::SameLine();
    if (ImGui::Button("Discard them")) answer = RecoveryAnswer::Discard;
    ImGui::SameLine();
    if (ImGui::Button("Not now") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) answer = RecoveryAnswer::Keep;
    if (answer != RecoveryAnswer::None) {
        asking = false;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
    return answer;
}

}  // namespace trazo
