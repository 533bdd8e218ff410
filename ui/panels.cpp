// ImGui panels: widgets straight onto the scene's fields; each returns the DirtyFlags of what it changed.
#include "panels.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace trazo {
namespace {

bool editVec3(const char* label, Vec3& v, float speed = 0.05f) { return ImGui::DragFloat3(label, &v.x, speed); }
bool editColor(const char* label, Vec3& c) {
    return ImGui::ColorEdit3(label, &c.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
}

// A combo over names with "(none)" first (index -1).
bool comboIndex(const char* label, int32_t& index, const std::vector<std::string>& names, bool allowNone) {
    const char* preview = index >= 0 && size_t(index) < names.size() ? names[size_t(index)].c_str() : "(none)";
    bool changed = false;
    if (ImGui::BeginCombo(label, preview)) {
        if (allowNone && ImGui::Selectable("(none)", index < 0)) {
            changed = index != -1;
            index = -1;
        }
        for (size_t i = 0; i < names.size(); ++i) {
            ImGui::PushID(int(i));
            if (ImGui::Selectable(names[i].c_str(), index == int32_t(i))) {
                changed = index != int32_t(i);
                index = int32_t(i);
            }
            ImGui::PopID();
        }
        ImGui::EndCombo();
    }
    return changed;
}

bool editPositiveInt(const char* label, int& v, int lo, int hi) {
    int value = v;
    if (!ImGui::InputInt(label, &value)) return false;
    value = std::clamp(value, lo, hi);
    if (value == v) return false;
    v = value;
    return true;
}

}  // namespace

DirtyFlags drawSceneSettingsPanel(SceneSettings& s) {
    DirtyFlags dirty = kDirtyNone;
    if (editColor("BackgroundColor", s.backgroundColor)) dirty |= kDirtyScene;
    // A new size reallocates the accumulation (and the display) when the field is left.
    int size[2] = {s.renderWidth, s.renderHeight};
    ImGui::InputInt2("Render size", size);
    if (ImGui::IsItemDeactivatedAfterEdit()) {
        s.renderWidth = std::clamp(size[0], 1, kMaxRenderSize);
        s.renderHeight = std::clamp(size[1], 1, kMaxRenderSize);
        dirty |= kDirtySize;
    }
    if (editPositiveInt("ReflectionQuality", s.reflectionQuality, 0, 64)) dirty |= kDirtyScene;
    if (editPositiveInt("ReflectionSteps", s.reflectionSteps, 0, 64)) dirty |= kDirtyScene;
    if (editPositiveInt("IndirectQuality", s.indirectQuality, 0, 64)) dirty |= kDirtyScene;
    if (ImGui::DragFloat("ColorBleeding", &s.colorBleeding, 0.01f, 0.0f, 100.0f)) dirty |= kDirtyScene;
    const int choices[] = {1, 4, 16};
    int aa = s.antialiasing == 16 ? 2 : s.antialiasing == 4 ? 1 : 0;
    if (ImGui::Combo("Antialiasing", &aa, "1\0" "4\0" "16\0")) {
        s.antialiasing = choices[aa];
        dirty |= kDirtyScene;
    }
    return dirty;
}

DirtyFlags drawCameraPanel(Camera& camera, PanelActions& actions) {
    DirtyFlags dirty = kDirtyNone;
    if (editVec3("POV", camera.pov)) dirty |= kDirtyCamera;
    if (editVec3("POI", camera.poi)) dirty |= kDirtyCamera;
    if (ImGui::SliderFloat("FOV", &camera.fovDegrees, 1.0f, 170.0f, "%.1f°")) dirty |= kDirtyCamera;
    if (ImGui::Button("Frame scene (F)")) actions.frameScene = true;
    ImGui::SameLine();
    if (ImGui::Button("File camera (R)")) actions.resetCamera = true;
    ImGui::TextDisabled("Left drag orbit · middle/shift drag pan · wheel dolly · WASD/QE fly");
    return dirty;
}

DirtyFlags drawMaterialsPanel(Scene& scene, PanelState& state) {
    if (scene.materials.empty()) {
        ImGui::TextDisabled("The scene declares no materials.");
        return kDirtyNone;
    }
    std::vector<std::string> names, textures;
    for (const Material& m : scene.materials) names.push_back(m.name);
    for (const Texture& t : scene.textures) textures.push_back(t.name);
    state.material = std::clamp(state.material, 0, int(names.size()) - 1);
    int32_t selected = state.material;
    if (comboIndex("Material", selected, names, false)) state.material = selected;
    Material& m = scene.materials[size_t(state.material)];
    DirtyFlags dirty = kDirtyNone;
    if (editColor("DiffuseColor", m.diffuseColor)) dirty |= kDirtyScene;
    if (editColor("SpecularColor", m.specularColor)) dirty |= kDirtyScene;
    if (editColor("EmissiveColor", m.emissiveColor)) dirty |= kDirtyScene;
    if (ImGui::SliderFloat("Roughness", &m.roughness, 0.0f, 1.0f)) dirty |= kDirtyScene;
    if (ImGui::SliderFloat("Opacity", &m.opacity, 0.0f, 1.0f)) dirty |= kDirtyScene;
    if (ImGui::DragFloat("RefractionIndex", &m.refractionIndex, 0.005f, 0.1f, 4.0f)) dirty |= kDirtyScene;
    if (ImGui::SliderFloat("ReflectionAngle", &m.reflectionAngleDegrees, 0.0f, 180.0f, "%.1f°")) dirty |= kDirtyScene;
    if (ImGui::SliderFloat("ReflectionAmount", &m.reflectionAmount, 0.0f, 1.0f)) dirty |= kDirtyScene;
    if (comboIndex("DiffuseTexture", m.diffuseTexture, textures, true)) dirty |= kDirtyScene;
    if (comboIndex("SpecularTexture", m.specularTexture, textures, true)) dirty |= kDirtyScene;
    if (comboIndex("EmissiveTexture", m.emissiveTexture, textures, true)) dirty |= kDirtyScene;
    if (comboIndex("NormalTexture", m.normalTexture, textures, true)) dirty |= kDirtyScene;
    m.refractionIndex = std::max(m.refractionIndex, 1e-3f);  // the reader's check: positive
    return dirty;
}

DirtyFlags drawLightsPanel(Scene& scene, PanelState& state) {
    DirtyFlags dirty = kDirtyNone;
    if (!scene.pointLights.empty()) {
        ImGui::SliderInt("Point light", &state.pointLight, 0, int(scene.pointLights.size()) - 1);
        state.pointLight = std::clamp(state.pointLight, 0, int(scene.pointLights.size()) - 1);
        PointLight& l = scene.pointLights[size_t(state.pointLight)];
        ImGui::PushID("point");
        if (editVec3("Position", l.position)) dirty |= kDirtyScene;
        if (editColor("Color", l.color)) dirty |= kDirtyScene;
        ImGui::PopID();
    }
    if (!scene.areaLights.empty()) {
        if (!scene.pointLights.empty()) ImGui::Separator();
        ImGui::SliderInt("Area light", &state.areaLight, 0, int(scene.areaLights.size()) - 1);
        state.areaLight = std::clamp(state.areaLight, 0, int(scene.areaLights.size()) - 1);
        AreaLight& l = scene.areaLights[size_t(state.areaLight)];
        ImGui::PushID("area");
        if (editVec3("Position", l.position)) dirty |= kDirtyScene;
        if (editColor("Color", l.color)) dirty |= kDirtyScene;
        Vec3 direction = l.direction;
        if (editVec3("Direction", direction, 0.01f) && lengthSquared(direction) > 0.0f) {
            l.direction = direction;
            dirty |= kDirtyScene;
        }
        if (ImGui::SliderAngle("RollAngle", &l.rollAngle, -180.0f, 180.0f)) dirty |= kDirtyScene;
        if (ImGui::DragFloat("Width", &l.width, 0.01f, 1e-3f, 1e4f)) dirty |= kDirtyScene;
        if (ImGui::DragFloat("Height", &l.height, 0.01f, 1e-3f, 1e4f)) dirty |= kDirtyScene;
        int sub[2] = {l.subdivisionX, l.subdivisionY};
        if (ImGui::InputInt2("Subdivision", sub)) {
            l.subdivisionX = std::clamp(sub[0], 1, 256);
            l.subdivisionY = std::clamp(sub[1], 1, 256);
            dirty |= kDirtyScene;
        }
        l.width = std::max(l.width, 1e-3f);
        l.height = std::max(l.height, 1e-3f);
        ImGui::PopID();
    }
    if (scene.pointLights.empty() && scene.areaLights.empty()) ImGui::TextDisabled("The scene has no lights.");
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
    ImGui::InputInt("Stop after", &state.targetPasses, 1, int(std::max(info.cyclePasses, 1u)));
    state.targetPasses = std::max(state.targetPasses, 0);
    ImGui::SameLine();
    ImGui::TextDisabled("(0: never)");
    if (ImGui::Button("Restart")) actions.restart = true;
    ImGui::SameLine();
    if (ImGui::Checkbox("Render at window size", &state.sizeFollowsWindow)) actions.dirty |= kDirtySize;
    ImGui::SliderFloat("Exposure", &state.tone.exposureStops, -8.0f, 8.0f, "%+.1f stops");
    ImGui::Combo("Tone", &state.tone.mode, "clamp (seed, = PNG)\0sRGB\0filmic\0");
    for (const std::string& u : info.unsupported) ImGui::TextWrapped("Not drawn yet: %s", u.c_str());
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
    ImGui::TextDisabled(".png/.bmp/.tga: the seed's clamp · .exr/.hdr/.pfm: linear float");
    ImGui::InputText("Scene", state.scenePath, sizeof state.scenePath);
    if (ImGui::Button("Save scene (Ctrl+S)")) actions.saveScene = true;
    if (!state.status.empty()) ImGui::TextWrapped("%s", state.status.c_str());
}

PanelActions drawPanels(Scene& scene, PanelState& state, const RenderInfo& info) {
    PanelActions actions;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(360, std::min(ImGui::GetIO().DisplaySize.y - 16.0f, 640.0f)), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (ImGui::Begin("Trazo")) {
        ImGui::PushItemWidth(-150);
        if (ImGui::CollapsingHeader("Scene settings")) actions.dirty |= drawSceneSettingsPanel(scene.settings);
        if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen))
            actions.dirty |= drawCameraPanel(scene.camera, actions);
        if (ImGui::CollapsingHeader("Materials")) actions.dirty |= drawMaterialsPanel(scene, state);
        if (ImGui::CollapsingHeader("Lights")) actions.dirty |= drawLightsPanel(scene, state);
        if (ImGui::CollapsingHeader("Render", ImGuiTreeNodeFlags_DefaultOpen)) drawRenderPanel(state, info, actions);
        if (ImGui::CollapsingHeader("Export", ImGuiTreeNodeFlags_DefaultOpen)) drawExportPanel(state, actions);
        ImGui::PopItemWidth();
    }
    ImGui::End();
    return actions;
}

}  // namespace trazo
