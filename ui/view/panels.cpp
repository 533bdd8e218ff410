// ImGui panels: the scene's parameters edited through the block tables' rows (param_editor.h's editRows picks
// each widget and its limits); each panel returns the DirtyFlags of what it changed.
#include "view/panels.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "model/environment_edit.h"
#include "model/setting_effects.h"
#include "scene/block_table.h"
#include "view/convergence_plot.h"
#include "view/param_editor.h"

namespace trazo {

namespace {

// EnvironmentMap: the path as the scene file writes it, read when the field is left after an edit (Enter
// leaves it too); a path that does not read leaves the old map and says why under the field.
DirtyFlags drawEnvironmentMapField(Scene& scene, PanelState& state) {
    if (!state.environmentEditing)
        std::snprintf(state.environmentPath, sizeof state.environmentPath, "%s", environmentMapText(scene).c_str());
    ImGui::InputTextWithHint("EnvironmentMap", "none: an equirectangular image", state.environmentPath,
                             sizeof state.environmentPath);
    const bool left = ImGui::IsItemDeactivatedAfterEdit();
    state.environmentEditing = ImGui::IsItemActive();
    DirtyFlags dirty = kDirtyNone;
    if (left && setEnvironmentMap(scene, state.environmentPath, state.environmentStatus)) dirty = kDirtyScene;
    if (!state.environmentStatus.empty()) {
        if (left) std::fprintf(stderr, "trazo: %s\n", state.environmentStatus.c_str());
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", state.environmentStatus.c_str());
        ImGui::PopStyleColor();
    }
    return dirty;
}

}  // namespace

DirtyFlags drawSceneSettingsPanel(Scene& scene, PanelState& state, Gestures& gestures) {
    DirtyFlags dirty = editRows(sceneSettingsTable(), scene.settings, sceneSettingEffect, &gestures);
    dirty |= drawEnvironmentMapField(scene, state);
    return dirty;
}

DirtyFlags drawCameraPanel(Camera& camera, PanelState& state, Gestures& gestures, PanelActions& actions) {
    const DirtyFlags dirty = editRows(cameraTable(), camera, cameraSettingEffect, &gestures);
    if (ImGui::Button("Frame scene (F)")) actions.commands.push_back(ViewerCommand::FrameScene);
    ImGui::SameLine();
    if (ImGui::Button("File camera (R)")) actions.commands.push_back(ViewerCommand::ResetCamera);
    ImGui::SameLine();
    if (ImGui::Button(state.focusPick ? "Click the image..." : "Focus here (Shift+F)"))
        actions.commands.push_back(ViewerCommand::FocusPick);
    if (state.focusPick) ImGui::TextDisabled("Click a surface: it becomes the FocalDistance · Escape cancels");
    ImGui::TextDisabled("Left drag orbit · middle/shift drag pan · wheel dolly · WASD/QE fly");
    return dirty;
}

DirtyFlags drawMaterialsPanel(Scene& scene, PanelState& state, Gestures& gestures) {
    if (scene.materials.empty()) {
        ImGui::TextDisabled("The scene declares no materials.");
        return kDirtyNone;
    }
    std::vector<std::string> names, textures;
    for (const Material& m : scene.materials) names.push_back(m.name);
    for (const Texture& t : scene.textures) textures.push_back(t.name);
    state.material = std::clamp(state.material, 0, int(names.size()) - 1);
    int32_t selected = state.material;
    if (comboIndex("Material", selected, names, nullptr)) state.material = selected;
    Material& m = scene.materials[size_t(state.material)];
    MaterialDraft draft{m, {}, {}};  // the reader's rows act on its draft
    DirtyFlags dirty = editRows(materialTable(), draft, kDirtyScene, &gestures);
    if (dirty) m = draft.material;
    for (size_t s = 0; s < kTextureSlotCount; ++s) {
        const bool changed = comboIndex(std::string(textureSlots()[s].name).c_str(), m.textures[s], textures, "(none)");
        trackGesture(gestures, changed);
        if (changed) dirty |= kDirtyScene;
    }
    return dirty;
}

void drawRenderPanel(PanelState& state, const RenderInfo& info, PanelActions& actions) {
    ImGui::Text("Backend: %s (%s)", info.backend.c_str(), info.device.c_str());
    BackendChoice choice = state.backend;
    if (ImGui::RadioButton("CPU", choice == BackendChoice::Cpu)) choice = BackendChoice::Cpu;
    ImGui::SameLine();
    if (!info.cudaBuilt) ImGui::BeginDisabled();
    if (ImGui::RadioButton("CUDA", choice == BackendChoice::Cuda)) choice = BackendChoice::Cuda;
    if (!info.cudaBuilt) ImGui::EndDisabled();
    if (choice != state.backend) {
        state.backend = choice;
        actions.switchBackend = true;
    }
    ImGui::Text("Display: %s", info.displayPath.c_str());
    ImGui::Text("Image %u x %u, full cycle %u passes", info.width, info.height, info.cyclePasses);
    ImGui::Text("Passes: %u, worth %.0f of one stratum (blocks %s)", info.passes, info.samples, info.blocks.c_str());
    if (state.targetPasses > 0) {
        ImGui::SameLine();
        ImGui::Text("(%.0f to go)", std::max(0.0, state.targetPasses - info.samples));
    }
    ImGui::Text("%.3g samples/s  %.3g Mrays/s  %.1f s", info.samplesPerSecond, info.mraysPerSecond, info.elapsedSeconds);
    if (info.convergence.empty()) {
        ImGui::TextDisabled("Error estimate: after two passes");
    } else {
        ImGui::Text("Error estimate: %.3g %% (the two halves)%s", 100.0 * info.convergence.back().second,
                    info.targetReached ? ", target reached" : "");
        drawConvergencePlot(info.convergence, state.targetErrorPercent / 100.0);
    }
    ImGui::InputInt("Stop after", &state.targetPasses, 1, int(std::max(info.cyclePasses, 1u)));
    state.targetPasses = std::max(state.targetPasses, 0);
    ImGui::SameLine();
    ImGui::TextDisabled("(0: never)");
    if (ImGui::InputFloat("Stop at error %", &state.targetErrorPercent, 0.1f, 1.0f, "%.2f")) {
        state.targetErrorPercent = std::clamp(state.targetErrorPercent, 0.0f, 100.0f);
        actions.targetErrorChanged = true;
    }
    ImGui::SameLine();
    ImGui::TextDisabled("(0: never)");
    if (ImGui::Button("Restart")) actions.restart = true;
    ImGui::SameLine();
    if (ImGui::Checkbox("Render at window size", &state.sizeFollowsWindow)) actions.dirty |= kDirtySize;
    ImGui::TextDisabled("Exposure and ViewTransform: Scene settings (shown as a PNG stores them)");
    for (const std::string& u : info.unsupported) ImGui::TextWrapped("%s", u.c_str());
}

void drawExportPanel(PanelState& state, PanelActions& actions) {
    ImGui::InputText("Image", state.screenshotPath, sizeof state.screenshotPath);
    if (ImGui::Button("Save image (P)")) actions.screenshot = true;
    ImGui::SameLine();
    if (ImGui::Button("New name")) actions.newScreenshotName = true;
    for (const char* extension : {".png", ".exr"}) {  // switch the format by the name's extension
        ImGui::SameLine();
        if (ImGui::SmallButton(extension)) {
            std::string path = state.screenshotPath;
            const size_t dot = path.find_last_of('.');
            const size_t slash = path.find_last_of('/');
            if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) path.erase(dot);
            std::snprintf(state.screenshotPath, sizeof state.screenshotPath, "%s%s", path.c_str(), extension);
        }
    }
    ImGui::TextDisabled(".png/.bmp/.tga: as shown · .exr/.hdr/.pfm: linear float");
    ImGui::InputText("Scene", state.scenePath, sizeof state.scenePath);
    if (ImGui::Button("Save scene (Ctrl+S)")) actions.saveScene = true;
    if (!state.status.empty()) ImGui::TextWrapped("%s", state.status.c_str());
}

void drawOpenPanel(PanelState& state, PanelActions& actions) {
    if (state.focusOpenPath) ImGui::SetKeyboardFocusHere();
    state.focusOpenPath = false;
    // Focused (a click, Ctrl+O), the whole path is selected: typing replaces it.
    if (ImGui::InputText("Path", state.openPath, sizeof state.openPath,
                         ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll))
        actions.open = true;
    ImGui::SameLine();
    if (ImGui::Button("Open")) actions.open = true;
    ImGui::TextDisabled("or drop a .scene file onto the window");
    if (state.openMessages.empty()) return;
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    for (const std::string& m : state.openMessages) ImGui::TextWrapped("%s", m.c_str());
    ImGui::PopStyleColor();
    if (ImGui::SmallButton("Dismiss")) state.openMessages.clear();
}

float drawMenuBar(const MenuInfo& info, PanelActions& actions) {
    if (!ImGui::BeginMainMenuBar()) return 0.0f;
    const auto item = [&](const char* label, const char* keys, ViewerCommand command, bool enabled = true,
                          bool checked = false) {
        if (ImGui::MenuItem(label, keys, checked, enabled)) actions.commands.push_back(command);
    };
    if (ImGui::BeginMenu("File")) {
        item("Open...", "Ctrl+O", ViewerCommand::OpenPrompt);
        item("Save scene", "Ctrl+S", ViewerCommand::SaveScene);
        item("Save image", "P", ViewerCommand::Screenshot);
        ImGui::Separator();
        item("Quit", "Ctrl+Q", ViewerCommand::Quit);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        item(info.canUndo ? ("Undo " + info.undoLabel).c_str() : "Undo", "Ctrl+Z", ViewerCommand::Undo, info.canUndo);
        item(info.canRedo ? ("Redo " + info.redoLabel).c_str() : "Redo", "Ctrl+Shift+Z", ViewerCommand::Redo,
             info.canRedo);
        ImGui::Separator();
        item("Add sphere", "Shift+A", ViewerCommand::AddSphere);
        item("Move selection", "G", ViewerCommand::Grab, info.hasSelection);
        item("Duplicate", "Shift+D", ViewerCommand::Duplicate, info.hasSelection);
        item("Delete", "X / Delete", ViewerCommand::Delete, info.hasSelection);
        item("Clear selection", "Escape", ViewerCommand::Cancel, info.hasSelection);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        item("Fit", "0", ViewerCommand::FitView, true, info.fitted);
        item("Actual pixels (1:1)", "1", ViewerCommand::ActualPixels);
        item("Zoom in", "+ / Ctrl+wheel", ViewerCommand::ZoomIn);
        item("Zoom out", "-", ViewerCommand::ZoomOut);
        ImGui::Separator();
        item("Frame scene", "F", ViewerCommand::FrameScene);
        item("File camera", "R", ViewerCommand::ResetCamera);
        item("Focus on a click", "Shift+F", ViewerCommand::FocusPick);
        ImGui::EndMenu();
    }
    const float height = ImGui::GetWindowSize().y;
    ImGui::EndMainMenuBar();
    return height;
}

void beginSidePanel(PanelState& state, float top) {
    const ImGuiIO& io = ImGui::GetIO();
    const float height = std::max(io.DisplaySize.y - top, 1.0f);
    const float scale = ImGui::GetFontSize() / 13.0f;  // the content scale the font was made for
    const float most = std::max(kMinPanelWidth * scale, io.DisplaySize.x * kMaxPanelShare);
    ImGui::SetNextWindowPos(ImVec2(0, top), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(state.panelWidth, height), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(kMinPanelWidth * scale, height), ImVec2(most, height));
    ImGui::Begin("Trazo", nullptr, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                                       ImGuiWindowFlags_NoBringToFrontOnFocus);
    // The edge drag resizes the window this frame: keep its width for the next (and for the image's area).
    state.panelWidth = ImGui::GetWindowWidth();
    ImGui::PushItemWidth(-150 * scale);
}

void drawSidePanelSections(Scene& scene, PanelState& state, const RenderInfo& info, ObjectsPanelState& objects,
                           Vec3 viewCentre, PanelActions& actions) {
    // A failed open shows why; Ctrl+O opens the section with its path field focused.
    if (!state.openMessages.empty() || state.focusOpenPath) ImGui::SetNextItemOpen(true);
    if (ImGui::CollapsingHeader("Open scene")) drawOpenPanel(state, actions);
    // The Objects panel starts the frame's gestures (startGestures): it comes before the other editors.
    if (objects.scrollToSelection) ImGui::SetNextItemOpen(true);
    if (ImGui::CollapsingHeader("Objects", ImGuiTreeNodeFlags_DefaultOpen)) {
        actions.dirty |= drawObjectsPanel(scene, objects, actions.objects, viewCentre);
    } else {
        startGestures(objects.gestures);
    }
    if (actions.dirty) actions.label = actions.objects.label;
    const auto edited = [&](DirtyFlags dirty, const std::string& label) {
        if (!dirty) return;
        actions.dirty |= dirty;
        actions.label = label;
    };
    if (ImGui::CollapsingHeader("Scene settings"))
        edited(drawSceneSettingsPanel(scene, state, objects.gestures), "Edit scene settings");
    if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen))
        edited(drawCameraPanel(scene.camera, state, objects.gestures, actions), "Edit camera");
    if (ImGui::CollapsingHeader("Materials")) {
        const DirtyFlags dirty = drawMaterialsPanel(scene, state, objects.gestures);
        if (dirty) edited(dirty, "Edit material " + scene.materials[size_t(state.material)].name);
    }
    actions.gesture = objects.gestures.edited;
    if (ImGui::CollapsingHeader("Render", ImGuiTreeNodeFlags_DefaultOpen)) drawRenderPanel(state, info, actions);
    if (ImGui::CollapsingHeader("Export", ImGuiTreeNodeFlags_DefaultOpen)) drawExportPanel(state, actions);
}

void endSidePanel() {
    ImGui::PopItemWidth();
    ImGui::End();
}

}  // namespace trazo
