// ViewerApp's input: the window's gestures, camera navigation, commands and the panels' actions, each an edit
// of the session's scene or of the view (viewer_frame_loop.h).
#include "view/viewer_frame_loop.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "render/render_start.h"

namespace trazo {

namespace {

constexpr float kZoomStep = 1.25f;  // per wheel notch or +/- press

}  // namespace

bool ViewerApp::applyInput(double dt) {
    const ImGuiIO& io = ImGui::GetIO();
    window_.setImageArea(area_.x / framebufferScale_, area_.y / framebufferScale_, area_.width / framebufferScale_,
                         area_.height / framebufferScale_);
    window_.setUiCapture(io.WantCaptureMouse, io.WantCaptureKeyboard);
    window_.setMoving(editor_.moving());
    const InputEvents e = window_.takeEvents();
    const bool flying = navigate(e, dt);
    if (e.viewPanX != 0 || e.viewPanY != 0)
        view_.panBy(e.viewPanX * framebufferScale_, e.viewPanY * framebufferScale_, area_, session_.renderWidth(),
                    session_.renderHeight());
    if (e.zoom != 0)
        view_.zoomBy(std::pow(kZoomStep, e.zoom), e.zoomAt.x * framebufferScale_, e.zoomAt.y * framebufferScale_,
                     area_, session_.renderWidth(), session_.renderHeight());
    for (const CursorPoint& c : e.clicks) {
        const std::optional<ImagePoint> p = onImage(c);
        if (!p) continue;
        if (state_.focusPick) {  // "Focus here": this click sets the focus (the background: nothing) and ends it
            state_.focusPick = false;
            markEdited(editor_.focusAt(*p));
        } else {
            editor_.click(*p);
        }
    }
    if (e.moveStarted) {  // Alt+drag takes the object under the cursor, then moves it
        if (auto p = onImage(e.moveStart)) editor_.click(*p);
        editor_.beginMove(toImage(e.moveStart));
    }
    if (editor_.moving() && editor_.updateMove(toImage(window_.cursor()), e.scroll)) {
        stats_.moveInput(Clock::now());
        markEdited(kDirtyScene);
    }
    if (e.moveEnded) markEdited(editor_.confirmMove());
    for (const ViewerCommand command : e.commands) markEdited(execute(command));
    for (const std::string& path : e.drops) files_.requestOpen(path);
    return flying;
}

bool ViewerApp::navigate(const InputEvents& e, double dt) {
    Camera& camera = session_.scene().camera;
    const auto moved = [&](const Camera& before, const char* kind) {
        editor_.cameraMoved(before, kind);
        markEdited(kDirtyCamera);
    };
    const Camera before = camera;
    if (e.orbitX != 0 || e.orbitY != 0) {
        controller_.orbit(camera, e.orbitX, e.orbitY);
        moved(before, "Orbit");
    }
    if (e.panX != 0 || e.panY != 0) {  // the drag in framebuffer pixels against the image's height on screen
        controller_.pan(camera, e.panX * framebufferScale_, e.panY * framebufferScale_, imageRect().height);
        moved(before, "Pan");
    }
    if (e.scroll != 0 && !editor_.moving()) {
        controller_.dolly(camera, e.scroll);
        moved(before, "Dolly");
    }
    const FlyKeys fly = window_.flyKeys();
    if (fly.moving()) {
        controller_.fly(camera, fly.forward, fly.right, fly.up, float(dt));
        moved(before, "Fly");
    }
    return fly.moving();
}

DirtyFlags ViewerApp::execute(ViewerCommand command) {
    Camera& camera = session_.scene().camera;
    const Camera before = camera;
    switch (command) {
        case ViewerCommand::FrameScene:
            controller_.frame(camera, sceneBounds(session_.arrays()));
            editor_.cameraMoved(before, "Frame");
            return kDirtyCamera;
        case ViewerCommand::ResetCamera:
            controller_.reset(camera, session_.fileScene().camera);
            editor_.cameraMoved(before, "Reset");
            return kDirtyCamera;
        case ViewerCommand::Screenshot: screenshotPending_ = true; break;
        case ViewerCommand::SaveScene: files_.save(); break;
        case ViewerCommand::Quit: window_.requestClose(); break;
        case ViewerCommand::Undo: return resized(editor_.undo());
        case ViewerCommand::Redo: return resized(editor_.redo());
        case ViewerCommand::FitView: view_.fit(); break;
        case ViewerCommand::ActualPixels: view_.actualPixels(); break;
        case ViewerCommand::ZoomIn:
        case ViewerCommand::ZoomOut:
            view_.zoomBy(command == ViewerCommand::ZoomIn ? kZoomStep : 1.0f / kZoomStep,
                         area_.x + 0.5f * area_.width, area_.y + 0.5f * area_.height, area_,
                         session_.renderWidth(), session_.renderHeight());
            break;
        case ViewerCommand::Grab: editor_.beginMove(toImage(window_.cursor())); break;
        case ViewerCommand::Confirm: return editor_.confirmMove() & ~kDirtyScene;  // the moves marked it
        case ViewerCommand::FocusPick: state_.focusPick = !state_.focusPick; break;
        case ViewerCommand::Cancel:
            if (state_.focusPick) {
                state_.focusPick = false;
                break;
            }
            if (editor_.moving()) return editor_.cancelMove();
            editor_.clearSelection();
            break;
        case ViewerCommand::Delete: return editor_.deleteSelected();
        case ViewerCommand::Duplicate: {
            const DirtyFlags dirty = editor_.duplicateSelected();
            if (dirty) editor_.beginMove(toImage(window_.cursor()));  // the copy follows the mouse, as G
            return dirty;
        }
        case ViewerCommand::AddSphere: return editor_.addSphere(camera.poi);
        case ViewerCommand::OpenPrompt: state_.focusOpenPath = true; break;
    }
    return kDirtyNone;
}

DirtyFlags ViewerApp::resized(DirtyFlags dirty) {
    if (dirty & kDirtySize)
        session_.setRenderSize(uint32_t(session_.scene().settings.renderWidth),
                               uint32_t(session_.scene().settings.renderHeight));
    return dirty;
}

void ViewerApp::apply(const PanelActions& a) {
    DirtyFlags dirty = resized(a.dirty);
    if (a.restart) dirty |= kDirtyCamera;
    markEdited(dirty);
    if (a.switchBackend) switchBackend(state_.backend);
    if (a.screenshot) execute(ViewerCommand::Screenshot);
    if (a.newScreenshotName) exports_.renameScreenshot(state_);
    if (a.saveScene) execute(ViewerCommand::SaveScene);
    if (a.targetErrorChanged) session_.setTargetError(state_.targetErrorPercent / 100.0);
    if (a.open) files_.requestOpen(state_.openPath);
    for (const ViewerCommand command : a.commands) markEdited(execute(command));
}

void ViewerApp::markEdited(DirtyFlags dirty) {
    if (dirty & kDirtyDisplay) settleFrames_ = std::max(settleFrames_, 1);  // only redrawn: no restart, no preview
    dirty &= ~kDirtyDisplay;
    if (!dirty) return;
    lastEdit_ = Clock::now();
    session_.markDirty(dirty);
    editor_.invalidateOutline();
}

BackendChoice ViewerApp::runningBackend() const {
    return session_.backend().runsOnCuda() ? BackendChoice::Cuda : BackendChoice::Cpu;
}

void ViewerApp::switchBackend(BackendChoice choice) {
    std::string why;
    auto backend = createBackendFor(session_.arrays(), choice, options_.threads, why);
    if (backend) {
        session_.replaceBackend(std::move(backend));
        state_.status = "now rendering on " + session_.backend().name();
    } else {
        state_.backend = runningBackend();
        state_.status = "cannot use CUDA: " + why;
    }
}

}  // namespace trazo
