// The panels' state: plain data the ImGui panels (view/panels.h, view/objects_panel.h) draw and edit, and the
// model's controllers act on too (ExportController the Export fields, SceneEditor the selection and the
// gesture ids), so it lives in the model. No ImGui.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "model/object_commands.h"
#include "model/screen_layout.h"

namespace trazo {

// Gesture ids for EditHistory::commit: the edits of one held widget share one; grabbing a widget (or the
// viewer starting a drag, beginGesture) hands out the next. One-shot edits (a click, a combo choice) get 0.
struct Gestures {
    uint64_t serial = 0;  // the last id handed out
    uint64_t held = 0;    // the id of the widget held now
    uint64_t edited = 0;  // the gesture of this frame's latest edit (startGestures clears it)
};
inline uint64_t beginGesture(Gestures& g) { return ++g.serial; }

struct ObjectsPanelState {
    Selection selection;             // shared with picking in the image (and cleared by Escape)
    bool scrollToSelection = false;  // set when the selection changed elsewhere: the list scrolls to it once
    Gestures gestures;               // also what the viewer's own drags take their ids from (beginGesture)
    char filePath[1024] = {};        // an .obj or .csg to add, or to become the selected one's Source
    std::string status;              // why the last add or Source change failed
};

struct PanelState {
    int material = 0;  // selected in the Materials panel
    // The Scene settings panel's EnvironmentMap field: what is typed (the scene's path while not being edited),
    // and why the last path typed did not load.
    char environmentPath[1024] = {};
    bool environmentEditing = false;
    std::string environmentStatus;
    bool focusPick = false;  // "Focus here": the next click on the image sets the camera's FocalDistance
    BackendChoice backend = BackendChoice::Cpu;  // the Render panel's choice: Cpu or Cuda
    int targetPasses = 0;      // stop after this many one-stratum passes' worth of samples; 0 = keep going
    bool sizeFollowsWindow = false;  // the image area's size
    float targetErrorPercent = 0;    // stop when the estimated relative error is below it; 0 = keep going
    float panelWidth = kPanelWidth;  // window coordinates; its right edge drags it
    char openPath[1024] = {};
    bool focusOpenPath = false;  // the path field takes the keyboard next frame (Ctrl+O)
    std::vector<std::string> openMessages;  // why the last open failed (file:line: error: ...)
    char screenshotPath[1024] = {};
    char scenePath[1024] = {};
    std::string status;  // last export message
};

}  // namespace trazo
