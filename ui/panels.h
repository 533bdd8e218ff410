// The viewer's ImGui panels: free functions over the scene and a small panel state. They keep no static
// state, never call the backend, and return what changed; the frame loop (viewer_app.cpp) acts on it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dirty_flags.h"
#include "display.h"
#include "scene/scene.h"

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
};

struct PanelState {
    int material = 0;  // selected in the Materials panel
    int pointLight = 0, areaLight = 0;
    ToneSettings tone;
    BackendChoice backend = BackendChoice::Cpu;  // the Render panel's choice: Cpu or Cuda
    int targetPasses = 0;      // stop after this many one-stratum passes' worth of samples; 0 = keep going
    bool sizeFollowsWindow = false;
    char screenshotPath[1024] = {};
    char scenePath[1024] = {};
    std::string status;  // last export message
};

struct PanelActions {
    DirtyFlags dirty = kDirtyNone;
    bool frameScene = false, resetCamera = false, restart = false;
    bool switchBackend = false;  // to PanelState::backend
    bool screenshot = false, newScreenshotName = false, saveScene = false;
};

// The whole side panel: Scene settings, Camera, Materials, Lights, Render, Export.
PanelActions drawPanels(Scene& scene, PanelState& state, const RenderInfo& info);

DirtyFlags drawSceneSettingsPanel(SceneSettings& settings);
DirtyFlags drawCameraPanel(Camera& camera, PanelActions& actions);
DirtyFlags drawMaterialsPanel(Scene& scene, PanelState& state);
DirtyFlags drawLightsPanel(Scene& scene, PanelState& state);
void drawRenderPanel(PanelState& state, const RenderInfo& info, PanelActions& actions);
void drawExportPanel(PanelState& state, PanelActions& actions);

}  // namespace trazo
