// The viewer's ImGui panels: free functions over the scene and a small panel state. They keep no static
// state, never call the backend, and return what changed; the frame loop (viewer_app.cpp) acts on it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/dirty_flags.h"
#include "model/panel_state.h"
#include "model/screen_layout.h"
#include "scene/scene.h"
#include "view/objects_panel.h"
#include "view/viewer_command.h"

namespace trazo {

// What the Render panel shows (read from the session and the display by the frame loop).
struct RenderInfo {
    std::string backend, device, displayPath;
    bool cudaBuilt = false;
    uint32_t width = 0, height = 0;
    uint32_t passes = 0, cyclePasses = 1;
    double samples = 0;  // passes weighted by their blocks (ViewerSession::samples)
    std::string blocks;  // the current segment's (describeBlocks)
    double elapsedSeconds = 0, samplesPerSecond = 0, mraysPerSecond = 0;
    std::vector<std::string> unsupported;  // flatten's warnings (what is read but not drawn), formatted
    // The estimated relative error (RMS over the image, from the two halves' difference) against render time
    // since the last reset; empty before there is one.
    std::vector<std::pair<double, double>> convergence;
    bool targetReached = false;
};

// What the menu bar shows enabled or checked.
struct MenuInfo {
    bool canUndo = false, canRedo = false, hasSelection = false, fitted = true;
    std::string undoLabel, redoLabel;  // "Move Sphere 2", shown after Undo / Redo
};

struct PanelActions {
    DirtyFlags dirty = kDirtyNone;  // what the scene's editors changed: one undo step named `label`
    std::string label;
    uint64_t gesture = 0;  // non-zero while a widget is held (param_editor.h's Gestures)
    ObjectsPanelActions objects;
    bool restart = false;
    bool switchBackend = false;  // to PanelState::backend
    bool screenshot = false, newScreenshotName = false, saveScene = false;
    bool targetErrorChanged = false;
    bool open = false;  // the scene at PanelState::openPath
    std::vector<ViewerCommand> commands;  // from the menu bar and the buttons
};

// The menu bar (File, Edit, View) across the top; returns its height (window coordinates).
float drawMenuBar(const MenuInfo& info, PanelActions& actions);
// The side panel at the window's left edge below the menu bar (`top`), the whole height, never over the image;
// its width (PanelState::panelWidth) follows a drag of its right edge. Between begin and end, the sections:
// Open, Objects (objects_panel.h; new objects go to `viewCentre`; the lights are there), Scene settings,
// Camera, Materials, Render, Export. The editors share the Objects panel's gesture ids.
void beginSidePanel(PanelState& state, float top);
void drawSidePanelSections(Scene& scene, PanelState& state, const RenderInfo& info, ObjectsPanelState& objects,
                           Vec3 viewCentre, PanelActions& actions);
void endSidePanel();

// Scene settings: the table's rows (Exposure and ViewTransform flagged kDirtyDisplay) and the EnvironmentMap
// path field (PanelState's environment fields).
DirtyFlags drawSceneSettingsPanel(Scene& scene, PanelState& state, Gestures& gestures);
// Camera: the table's rows (the lens re-flattens), and the buttons: frame, file camera, focus on a click.
DirtyFlags drawCameraPanel(Camera& camera, PanelState& state, Gestures& gestures, PanelActions& actions);
DirtyFlags drawMaterialsPanel(Scene& scene, PanelState& state, Gestures& gestures);
void drawRenderPanel(PanelState& state, const RenderInfo& info, PanelActions& actions);
void drawExportPanel(PanelState& state, PanelActions& actions);
void drawOpenPanel(PanelState& state, PanelActions& actions);

}  // namespace trazo
