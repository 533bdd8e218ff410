// The viewer's frame loop. Each frame: the window's gestures and commands → camera, view and object edits
// (each an undo step through SceneEditor, marked dirty on the session); when the worker's batch of passes is
// done, show it (and the selection's outline), apply the edits (re-upload, reset) and start the next batch
// sized to the frame budget; build the menu bar and the side panel, apply their actions, draw the image in
// its area beside the panel (ViewTransform), present. Files and their questions are SceneFiles', names and
// image saves ExportController's, the closing line's numbers ViewerStats'.
#include "viewer_app.h"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "camera_controller.h"
#include "display.h"
#include "export_controller.h"
#include "image/image_writer.h"
#include "panels.h"
#include "render_info.h"
#include "render/progressive_render.h"
#include "render/render_start.h"
#include "render/strata_plan.h"
#include "scene/scene_reader.h"
#include "scene_editor.h"
#include "scene_files.h"
#include "screen_layout.h"
#include "view_transform.h"
#include "viewer_session.h"
#include "viewer_stats.h"
#include "window.h"

namespace trazo {
namespace {

using Clock = std::chrono::steady_clock;

constexpr uint32_t kDefaultTargetPasses = 1024;
// While the user moves the camera or edits (and for the very first image), passes that would take longer than
// this run at 1/2, 1/4 or 1/8 of the size, so the image follows the mouse; full size resumes kPreviewHold
// seconds after the last edit. Screenshots and --frames always use the full size.
constexpr double kPreviewPassSeconds = 1.0 / 20.0;
constexpr double kPreviewHoldSeconds = 0.25;
constexpr float kZoomStep = 1.25f;  // per wheel notch or +/- press

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

class ViewerApp {
public:
    ViewerApp(const ViewerOptions& options, Window& window, ViewerSession& session, Clock::time_point start,
              float panelWidth)
        : options_(options), window_(window), session_(session),
          exports_(options.scenePath, options.screenshot, state_), stats_(start), editor_(session, options.scenePath),
          files_(options.scenePath, !options.frames, session, editor_, exports_, state_, window) {
        state_.panelWidth = panelWidth;
        std::string device;
        cudaBuilt_ = cudaDeviceAvailable(device) || session.backend().name() == "cuda";
        state_.backend = runningBackend();
        state_.targetPasses = options.frames ? int(*options.frames)
                                             : int(std::max(kDefaultTargetPasses, session.cyclePasses()));
        session_.setOnBatchDone(&Window::wake);
        // Larger blocks while a pass still fits the batch budget, unless --blocks fixes them; --frames keeps one
        // stratum per pass, so its image is `--render --blocks 1 --spp N`.
        if (options.blocks) session_.setBlocks(*options.blocks, 0.0);
        else if (!options.frames) session_.setBlocks(StrataBlocks::ones(), ViewerSession::kBatchSeconds);
    }

    // The frame loop of Dear ImGui's examples (poll, build the UI, apply its actions, render, present), with the
    // renderer's batches stepped between the input and the UI, and a frame drawn only when something changed.
    int run(Display& display) {
        int status = 0;
        auto lastFrame = Clock::now();
        while (options_.frames ? !window_.shouldClose() : !files_.closing()) {
            waitForEvents();
            const auto frameStart = Clock::now();
            const double dt = std::min(std::chrono::duration<double>(frameStart - lastFrame).count(), 0.1);
            lastFrame = frameStart;
            const bool active = window_.takeActivity();
            if (applyInput(dt) || active) settleFrames_ = 3;

            bool imageChanged = false;
            if (!session_.busy()) {
                imageChanged = showFinishedBatch(display);
                if (options_.frames && session_.passes() >= *options_.frames && session_.dirty() == kDirtyNone) {
                    status = finishAutomation();
                    break;
                }
                if (editor_.refreshOutline(outline_)) {
                    display.setOutline(outline_, session_.renderWidth(), session_.renderHeight());
                    settleFrames_ = std::max(settleFrames_, 1);
                }
                startNextBatch();
            }
            // Redraw only when something changed: an idle window leaves the cores to the renderer.
            if (!active && !imageChanged && settleFrames_ <= 0 && stats_.frames() > 0) continue;
            drawFrame(display);
            const auto shown = Clock::now();
            stats_.frameShown(frameStart, shown, imageShown_, fullImageShown_, window_.dragging() || editor_.moving());
            if (imageChanged) stats_.imageShown(shown);
            if (state_.sizeFollowsWindow) followAreaSize();
            if (!active && settleFrames_ > 0) --settleFrames_;
            editor_.tick();
            updateTitle();
        }
        if (!options_.frames) editor_.quitting();
        printStats(display);
        return status;
    }

private:
    // The menu bar and the side panel (ImGui), then the image in the area beside them, then the UI over it.
    void drawFrame(Display& display) {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        const Scene before = session_.scene();  // for the undo step of what the panels change
        PanelActions actions;
        menuHeight_ = drawMenuBar(menuInfo(), actions);
        beginSidePanel(state_, menuHeight_);
        drawSidePanelSections(session_.scene(), state_, describeRender(session_, display, cudaBuilt_), editor_.objects(),
                              session_.scene().camera.poi, actions);
        endSidePanel();
        editor_.commit(before, actions.label, actions.dirty, actions.gesture);
        if (actions.objects.selectionChanged) editor_.reportSelection();
        apply(actions);
        markEdited(resized(files_.drawDialogs()));
        ImGui::Render();
        int fbw, fbh;
        window_.framebufferSize(fbw, fbh);
        updateArea();
        display.draw(fbw, fbh, area_, imageRect(), state_.tone);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        window_.swapBuffers();
    }

    // The image's area beside the panel, in framebuffer pixels (as the panel's width stands this frame).
    void updateArea() {
        int w, h, fbw, fbh;
        window_.windowSize(w, h);
        window_.framebufferSize(fbw, fbh);
        area_ = imageArea(w, h, fbw, fbh, state_.panelWidth, menuHeight_);
        framebufferScale_ = w > 0 ? float(fbw) / float(w) : 1.0f;
    }
    // Where the full-size image is shown (a preview's smaller accumulation is stretched over the same place).
    ImageRect imageRect() const { return view_.rect(area_, session_.renderWidth(), session_.renderHeight()); }
    // A window point in the full-size image's pixels (beyond its edges too: a move's cursor).
    ImagePoint toImage(CursorPoint c) const {
        return view_.toImage(c.x * framebufferScale_, c.y * framebufferScale_, area_, session_.renderWidth(),
                             session_.renderHeight());
    }
    // The same for a point that must be on the image (a click); none beside it.
    std::optional<ImagePoint> onImage(CursorPoint c) const {
        return view_.imagePoint(c.x * framebufferScale_, c.y * framebufferScale_, area_, session_.renderWidth(),
                                session_.renderHeight());
    }

    MenuInfo menuInfo() const {
        MenuInfo info;
        const EditHistory& h = editor_.history();
        info.canUndo = h.canUndo();
        info.canRedo = h.canRedo();
        info.undoLabel = h.undoLabel();
        info.redoLabel = h.redoLabel();
        info.hasSelection = editor_.selection().has_value();
        info.fitted = view_.fitted();
        return info;
    }

    void updateTitle() {
        const std::string title = "trazo — " + std::filesystem::path(files_.scenePath()).filename().string() +
                                  (editor_.unsaved() ? " *" : "");
        if (title == title_) return;
        title_ = title;
        window_.setTitle(title);
    }

    // Woken early by input or by the batch's end (Window::wake); ImGui gets a few frames to settle.
    void waitForEvents() {
        const bool finished = ((state_.targetPasses > 0 && session_.samples() >= double(state_.targetPasses)) ||
                               session_.targetReached()) &&
                              session_.dirty() == kDirtyNone && !screenshotPending_;
        if (session_.busy() || (finished && session_.generation() == shownGeneration_)) {
            window_.waitEvents(settleFrames_ > 0 ? 1.0 / 60.0 : 0.5);
        } else {
            window_.pollEvents();
        }
    }

    // Puts the finished batch on screen; true when the image changed. After a reset the last image stays up
    // until the first new passes are done (no black flash).
    bool showFinishedBatch(Display& display) {
        if (session_.generation() == shownGeneration_ || session_.passes() == 0) return false;
        display.update(session_.backend(), session_.width(), session_.height());
        shownGeneration_ = session_.generation();
        imageShown_ = true;
        if (session_.previewDivisor() == 1) fullImageShown_ = true;
        return true;
    }

    // A pending screenshot, then the edits, then passes sized to the batch budget.
    void startNextBatch() {
        if (screenshotPending_ && session_.dirty() == kDirtyNone && session_.passes() > 0 &&
            session_.previewDivisor() == 1) {
            screenshotPending_ = false;
            exports_.saveScreenshot(session_, state_);
        }
        if (!options_.frames) choosePreview();
        const uint32_t target = state_.targetPasses > 0 ? uint32_t(state_.targetPasses) : kMaxProgressivePasses;
        if (session_.dirty() != kDirtyNone) session_.applyEdits();
        if (session_.samples() < double(target) && !session_.targetReached()) {
            // The target counts one-stratum passes; a pass of a grown segment stands for several.
            const double left = (double(target) - session_.samples()) / session_.blocksWeight();
            const double budget = session_.passesForBudget(ViewerSession::kBatchSeconds);
            session_.startPasses(uint32_t(std::clamp(std::ceil(left), 1.0, budget)));
            stats_.batchStarted();
        }
    }

    void choosePreview() {
        const bool starting = !imageShown_ && session_.passes() == 0;
        const bool editing = lastEdit_ != Clock::time_point{} && secondsSince(lastEdit_) < kPreviewHoldSeconds;
        uint32_t divisor = 1;
        if ((starting || editing) && !screenshotPending_) {
            const double perPixel = session_.secondsPerPixelPass();
            const double fullPass = perPixel * session_.renderWidth() * session_.renderHeight();
            if (perPixel <= 0.0) {
                divisor = 4;  // cost unknown before the first pass: a quick quarter-size first image
            } else {
                while (divisor < 8 && fullPass / (divisor * divisor) > kPreviewPassSeconds) divisor *= 2;
            }
        }
        session_.setPreviewDivisor(divisor);
    }

    // The window's gestures and commands; true while the camera is flying (keys held send no events, yet the
    // frames must go on).
    bool applyInput(double dt) {
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
        for (const CursorPoint& c : e.clicks)
            if (auto p = onImage(c)) editor_.click(*p);
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

    // The camera's navigation: orbit, pan, dolly (the wheel, unless a move takes it), fly; each an edit.
    bool navigate(const InputEvents& e, double dt) {
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

    // One command, from a key, the menu or a panel button; what of the scene it changed.
    DirtyFlags execute(ViewerCommand command) {
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
            case ViewerCommand::Cancel:
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

    // Edits that change the render size reallocate (an undo of a Scene settings edit, say).
    DirtyFlags resized(DirtyFlags dirty) {
        if (dirty & kDirtySize)
            session_.setRenderSize(uint32_t(session_.scene().settings.renderWidth),
                                   uint32_t(session_.scene().settings.renderHeight));
        return dirty;
    }

    void apply(const PanelActions& a) {
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

    // Edits restart the image, at preview size for kPreviewHoldSeconds; the outline waits for the new image.
    void markEdited(DirtyFlags dirty) {
        if (!dirty) return;
        lastEdit_ = Clock::now();
        session_.markDirty(dirty);
        editor_.invalidateOutline();
    }

    BackendChoice runningBackend() const {
        return session_.backend().name() == "cuda" ? BackendChoice::Cuda : BackendChoice::Cpu;
    }

    void switchBackend(BackendChoice choice) {
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

    // Render at the image area's size: the accumulation (and the display) are reallocated when it changes.
    void followAreaSize() {
        SceneSettings& s = session_.scene().settings;
        const int w = int(area_.width), h = int(area_.height);
        if (w <= 0 || h <= 0 || (s.renderWidth == w && s.renderHeight == h)) return;
        s.renderWidth = std::min(w, kMaxRenderSize);
        s.renderHeight = std::min(h, kMaxRenderSize);
        session_.setRenderSize(uint32_t(s.renderWidth), uint32_t(s.renderHeight));
        session_.markDirty(kDirtyCamera);
    }

    int finishAutomation() {
        if (options_.screenshot.empty()) return 0;
        std::string message;
        if (!saveSessionImage(session_, options_.screenshot, message)) {
            std::fprintf(stderr, "trazo: %s\n", message.c_str());
            return 1;
        }
        return 0;
    }

    void printStats(const Display& display) {
        if (options_.quiet) return;
        session_.waitIdle();
        const double perPass = session_.passes() ? session_.renderSeconds() / session_.passes() : 0.0;
        std::fprintf(stderr, "trazo: viewer %ux%u on %s (%s), display through %s: %s; %u passes since the last reset "
                             "(%.3f s/pass, %.2f Mrays/s)\n",
                     session_.renderWidth(), session_.renderHeight(), session_.backend().name().c_str(),
                     session_.backend().deviceName().c_str(), displayPathName(display.path()),
                     stats_.summary(Clock::now()).c_str(), session_.passes(), perPass,
                     session_.renderSeconds() > 0 ? double(session_.rays()) / session_.renderSeconds() * 1e-6 : 0.0);
    }

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
    ViewTransform view_;
    ImageRect area_;
    float menuHeight_ = 0, framebufferScale_ = 1;
    std::vector<uint8_t> outline_;
};

// HiDPI: the font is made at the screen's content scale and drawn at 1 / (framebuffer pixels per window
// coordinate), the sizes scaled to match; returns the UI's scale in window coordinates per UI point (1 on a
// plain screen; 2 on an X11 or Windows screen at 200 %; 1 on a Retina screen, whose framebuffer is twice the
// window instead).
float setUpUiScale(const Window& window) {
    const float content = window.screen().contentScale, framebuffer = window.framebufferScale();
    ImGuiIO& io = ImGui::GetIO();
    ImFontConfig font;
    font.SizePixels = 13.0f * content;
    io.Fonts->AddFontDefault(&font);
    io.FontGlobalScale = 1.0f / framebuffer;
    const float uiScale = content / framebuffer;
    ImGui::GetStyle().ScaleAllSizes(uiScale);
    return uiScale;
}

}  // namespace

int runViewer(const ViewerOptions& options) {
    const auto start = Clock::now();
    if (!options.screenshot.empty()) {
        ImageFormat format;
        if (!imageFormatFromPath(options.screenshot, format)) {
            std::fprintf(stderr, "trazo: %s\n", unknownImageFormatReason(options.screenshot).c_str());
            return 2;
        }
    }
    Diagnostics diags;
    Scene scene = readSceneFile(options.scenePath, diags);
    if (!diags.hasErrors()) checkRenderBounds(scene, diags);  // as headless: no grid the kernels cannot count
    printDiagnostics(diags);
    if (diags.hasErrors()) return 2;

    const uint32_t width = options.width ? options.width : uint32_t(scene.settings.renderWidth);
    const uint32_t height = options.height ? options.height : uint32_t(scene.settings.renderHeight);
    scene.settings.renderWidth = int(width);  // the Scene settings panel shows the size in use
    scene.settings.renderHeight = int(height);
    std::string error;
    std::unique_ptr<Window> window =
        Window::open("trazo — " + std::filesystem::path(options.scenePath).filename().string(), error);
    if (!window) {
        std::fprintf(stderr, "trazo: cannot open the viewer: %s; render without a window with `trazo --render %s -o image.png`\n",
                     error.c_str(), options.scenePath.c_str());
        return 1;
    }

    int status = 0;
    try {
        std::string fallback;
        std::unique_ptr<Backend> backend = openBackend(options.backend, options.threads, nullptr, fallback);
        if (!backend) return 1;
        if (!options.quiet)
            std::fprintf(stderr, "trazo: viewer on %s; GL %s\n", describeBackend(*backend, fallback).c_str(),
                         reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
        Display display;
        if (!display.init(error)) {
            std::fprintf(stderr, "trazo: cannot open the viewer: %s; render without a window with `trazo --render %s`\n",
                         error.c_str(), options.scenePath.c_str());
            return 1;
        }
        ViewerSession session(std::move(scene), std::move(backend), options.seed, width, height);
        if (!options.quiet) printDiagnostics(session.flattenWarnings());

        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
        ImGui::StyleColorsDark();
        const float uiScale = setUpUiScale(*window);
        int windowWidth, windowHeight;
        initialWindowSize(width, height, kPanelWidth * uiScale, 13.0f * uiScale + 2 * ImGui::GetStyle().FramePadding.y,
                          window->framebufferScale(),
                          window->screen().width, window->screen().height, windowWidth, windowHeight);
        window->show(windowWidth, windowHeight);
        ImGui_ImplGlfw_InitForOpenGL(window->handle(), true);  // chains to the window's own callbacks
        ImGui_ImplOpenGL3_Init("#version 330 core");
        {
            ViewerApp app(options, *window, session, start, kPanelWidth * uiScale);
            status = app.run(display);
        }
        session.waitIdle();
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "trazo: %s\n", e.what());
        return 1;
    }
    return status;
}

}  // namespace trazo
