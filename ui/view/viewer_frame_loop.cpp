// ViewerApp's frame loop, its drawing and its batches (viewer_frame_loop.h).
#include "view/viewer_frame_loop.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "render/progressive_render.h"
#include "render/render_start.h"
#include "view/render_info.h"

namespace trazo {

namespace {

constexpr uint32_t kDefaultTargetPasses = 1024;
// While the user moves the camera or edits (and for the very first image), passes that would take longer than
// this run at 1/2, 1/4 or 1/8 of the size, so the image follows the mouse; full size resumes kPreviewHold
// seconds after the last edit. Screenshots and --frames always use the full size.
constexpr double kPreviewPassSeconds = 1.0 / 20.0;
constexpr double kPreviewHoldSeconds = 0.25;

double secondsSince(ViewerApp::Clock::time_point t0) {
    return std::chrono::duration<double>(ViewerApp::Clock::now() - t0).count();
}

}  // namespace

ViewerApp::ViewerApp(const ViewerOptions& options, Window& window, ViewerSession& session, Clock::time_point start,
                     float panelWidth)
    : options_(options), window_(window), session_(session),
      exports_(options.scenePath, options.screenshot, state_), stats_(start), editor_(session, options.scenePath),
      files_(options.scenePath, !options.frames, session, editor_, exports_, state_, window) {
    state_.panelWidth = panelWidth;
    std::string device;
    cudaBuilt_ = cudaDeviceAvailable(device) || session.backend().runsOnCuda();
    state_.backend = runningBackend();
    state_.targetPasses = options.frames ? int(*options.frames)
                                         : int(std::max(kDefaultTargetPasses, session.accumulation().cyclePasses()));
    session_.setOnBatchDone(&Window::wake);
    // Larger blocks while a pass still fits the batch budget, unless --blocks fixes them; --frames keeps one
    // stratum per pass, so its image is `--render --blocks 1 --spp N`.
    if (options.blocks) session_.setBlocks(*options.blocks, 0.0);
    else if (!options.frames) session_.setBlocks(StrataBlocks::ones(), ViewerSession::kBatchSeconds);
}

int ViewerApp::run(Display& display) {
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
            if (options_.frames && session_.accumulation().passes() >= *options_.frames &&
                session_.dirty() == kDirtyNone) {
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

void ViewerApp::drawFrame(Display& display) {
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
    display.draw(fbw, fbh, area_, imageRect(), shownTone(session_.scene().settings, state_.tone));  // = a screenshot
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    window_.swapBuffers();
}

void ViewerApp::updateArea() {
    int w, h, fbw, fbh;
    window_.windowSize(w, h);
    window_.framebufferSize(fbw, fbh);
    area_ = imageArea(w, h, fbw, fbh, state_.panelWidth, menuHeight_);
    framebufferScale_ = w > 0 ? float(fbw) / float(w) : 1.0f;
}

ImagePoint ViewerApp::toImage(CursorPoint c) const {
    return view_.toImage(c.x * framebufferScale_, c.y * framebufferScale_, area_, session_.renderWidth(),
                         session_.renderHeight());
}

std::optional<ImagePoint> ViewerApp::onImage(CursorPoint c) const {
    return view_.imagePoint(c.x * framebufferScale_, c.y * framebufferScale_, area_, session_.renderWidth(),
                            session_.renderHeight());
}

MenuInfo ViewerApp::menuInfo() const {
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

void ViewerApp::updateTitle() {
    const std::string title = "trazo — " + std::filesystem::path(files_.scenePath()).filename().string() +
                              (editor_.unsaved() ? " *" : "");
    if (title == title_) return;
    title_ = title;
    window_.setTitle(title);
}

void ViewerApp::waitForEvents() {
    const ProgressiveAccumulation& image = session_.accumulation();
    const bool finished = ((state_.targetPasses > 0 && image.samples() >= double(state_.targetPasses)) ||
                           image.targetReached()) &&
                          session_.dirty() == kDirtyNone && !screenshotPending_;
    if (session_.busy() || (finished && image.generation() == shownGeneration_)) {
        window_.waitEvents(settleFrames_ > 0 ? 1.0 / 60.0 : 0.5);
    } else {
        window_.pollEvents();
    }
}

bool ViewerApp::showFinishedBatch(Display& display) {
    if (session_.accumulation().generation() == shownGeneration_ || session_.accumulation().passes() == 0) return false;
    display.update(session_.backend(), session_.width(), session_.height());
    shownGeneration_ = session_.accumulation().generation();
    imageShown_ = true;
    if (session_.previewDivisor() == 1) fullImageShown_ = true;
    return true;
}

void ViewerApp::startNextBatch() {
    if (screenshotPending_ && session_.dirty() == kDirtyNone && session_.accumulation().passes() > 0 &&
        session_.previewDivisor() == 1) {
        screenshotPending_ = false;
        exports_.saveScreenshot(session_, state_);
    }
    if (!options_.frames) choosePreview();
    const uint32_t target = state_.targetPasses > 0 ? uint32_t(state_.targetPasses) : kMaxProgressivePasses;
    if (session_.dirty() != kDirtyNone) session_.applyEdits();
    if (session_.accumulation().samples() < double(target) && !session_.accumulation().targetReached()) {
        // The target counts one-stratum passes; a pass of a grown segment stands for several.
        const double left = (double(target) - session_.accumulation().samples()) / session_.accumulation().blocksWeight();
        const double budget = session_.passesForBudget(ViewerSession::kBatchSeconds);
        session_.startPasses(uint32_t(std::clamp(std::ceil(left), 1.0, budget)));
        stats_.batchStarted();
    }
}

void ViewerApp::choosePreview() {
    const bool starting = !imageShown_ && session_.accumulation().passes() == 0;
    const bool editing = lastEdit_ != Clock::time_point{} && secondsSince(lastEdit_) < kPreviewHoldSeconds;
    uint32_t divisor = 1;
    if ((starting || editing) && !screenshotPending_) {
        const double perPixel = session_.accumulation().secondsPerPixelPass();
        const double fullPass = perPixel * session_.renderWidth() * session_.renderHeight();
        if (perPixel <= 0.0) {
            divisor = 4;  // cost unknown before the first pass: a quick quarter-size first image
        } else {
            while (divisor < 8 && fullPass / (divisor * divisor) > kPreviewPassSeconds) divisor *= 2;
        }
    }
    session_.setPreviewDivisor(divisor);
}

void ViewerApp::followAreaSize() {
    SceneSettings& s = session_.scene().settings;
    const int w = int(area_.width), h = int(area_.height);
    if (w <= 0 || h <= 0 || (s.renderWidth == w && s.renderHeight == h)) return;
    s.renderWidth = std::min(w, kMaxRenderSize);
    s.renderHeight = std::min(h, kMaxRenderSize);
    session_.setRenderSize(uint32_t(s.renderWidth), uint32_t(s.renderHeight));
    session_.markDirty(kDirtyCamera);
}

int ViewerApp::finishAutomation() {
    if (options_.screenshot.empty()) return 0;
    std::string message;
    if (!saveSessionImage(session_, options_.screenshot, state_.tone, message)) {
        std::fprintf(stderr, "trazo: %s\n", message.c_str());
        return 1;
    }
    return 0;
}

void ViewerApp::printStats(const Display& display) {
    if (options_.quiet) return;
    session_.waitIdle();
    const double perPass = session_.accumulation().passes() ? session_.accumulation().renderSeconds() / session_.accumulation().passes() : 0.0;
    std::fprintf(stderr, "trazo: viewer %ux%u on %s (%s), display through %s: %s; %u passes since the last reset "
                         "(%.3f s/pass, %.2f Mrays/s)\n",
                 session_.renderWidth(), session_.renderHeight(), session_.backend().name().c_str(),
                 session_.backend().deviceName().c_str(), displayPathName(display.path()),
                 stats_.summary(Clock::now()).c_str(), session_.accumulation().passes(), perPass,
                 session_.accumulation().renderSeconds() > 0 ? double(session_.accumulation().rays()) / session_.accumulation().renderSeconds() * 1e-6 : 0.0);
}

}  // namespace trazo
