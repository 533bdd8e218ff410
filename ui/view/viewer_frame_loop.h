// ViewerApp: the viewer's frame loop and what it wires together. Each frame: the window's gestures and commands
// → camera, view and object edits (each an undo step through SceneEditor, marked dirty on the session); when
// the worker's batch of passes is done, show it (and the selection's outline), apply the edits (re-upload,
// reset) and start the next batch sized to the frame budget; build the menu bar and the side panel, apply
// their actions, draw the image in its area beside the panel (ImagePlacement), present. The loop and the image
// live in viewer_frame_loop.cpp, input and commands in viewer_input.cpp. Files and their questions are
// SceneFiles', names and image saves ExportController's, the closing line's numbers ViewerStats'.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/camera_controller.h"
#include "model/export_controller.h"
#include "model/scene_editor.h"
#include "model/screen_layout.h"
#include "model/image_placement.h"
#include "model/viewer_session.h"
#include "model/viewer_stats.h"
#include "view/display.h"
#include "view/panels.h"
#include "view/scene_files.h"
#include "view/viewer_app.h"
#include "view/window.h"

namespace trazo {

class ViewerApp {
public:
    using Clock = std::chrono::steady_clock;

    ViewerApp(const ViewerOptions& options, Window& window, ViewerSession& session, Clock::time_point start,
              float panelWidth);
    // The frame loop of Dear ImGui's examples (poll, build the UI, apply its actions, render, present), with the
    // renderer's batches stepped between the input and the UI, and a frame drawn only when something changed.
    int run(Display& display);

private:
    // The frame and the image (viewer_frame_loop.cpp).
    // The menu bar and the side panel (ImGui), then the image in the area beside them, then the UI over it.
    void drawFrame(Display& display);
    // The image's area beside the panel, in framebuffer pixels (as the panel's width stands this frame).
    void updateArea();
    // Where the full-size image is shown (a preview's smaller accumulation is stretched over the same place).
    ImageRect imageRect() const { return view_.rect(area_, session_.renderWidth(), session_.renderHeight()); }
    // A window point in the full-size image's pixels (beyond its edges too: a move's cursor).
    ImagePoint toImage(CursorPoint c) const;
    // The same for a point that must be on the image (a click); none beside it.
    std::optional<ImagePoint> onImage(CursorPoint c) const;
    MenuInfo menuInfo() const;
    void updateTitle();
    // Woken early by input or by the batch's end (Window::wake); ImGui gets a few frames to settle.
    void waitForEvents();
    // Puts the finished batch on screen; true when the image changed. After a reset the last image stays up
    // until the first new passes are done (no black flash).
    bool showFinishedBatch(Display& display);
    // A pending screenshot, then the edits, then passes sized to the batch budget.
    void startNextBatch();
    void choosePreview();
    // Render at the image area's size: the accumulation (and the display) are reallocated when it changes.
    void followAreaSize();
    int finishAutomation();
    void printStats(const Display& display);

    // Input and commands (viewer_input.cpp).
    // The window's gestures and commands; true while the camera is flying (keys held send no events, yet the
    // frames must go on).
    bool applyInput(double dt);
    // The camera's navigation: orbit, pan, dolly (the wheel, unless a move takes it), fly; each an edit.
    bool navigate(const InputEvents& e, double dt);
    // One command, from a key, the menu or a panel button; what of the scene it changed.
    DirtyFlags execute(ViewerCommand command);
    // Edits that change the render size reallocate (an undo of a Scene settings edit, say).
    DirtyFlags resized(DirtyFlags dirty);
    void apply(const PanelActions& a);
    // Edits restart the image, at preview size for kPreviewHoldSeconds; the outline waits for the new image.
    void markEdited(DirtyFlags dirty);
    BackendChoice runningBackend() const;
    void switchBackend(BackendChoice choice);

    const ViewerOptions& options_;
    Window& window_;
    ViewerSession& session_;
    std::string title_;
    CameraController controller_;
    PanelState state_;
    ExportController exports_;
    ViewerStats stats_;
    SceneEditor editor_;
    SceneFiles files_;
    bool cudaBuilt_ = false;
    bool screenshotPending_ = false;
    bool imageShown_ = false, fullImageShown_ = false;
    uint64_t shownGeneration_ = ~uint64_t(0);
    int settleFrames_ = 0;
    Clock::time_point lastEdit_{};
    ImagePlacement view_;
    ImageRect area_;
    float menuHeight_ = 0, framebufferScale_ = 1;
    std::vector<uint8_t> outline_;
};

}  // namespace trazo
