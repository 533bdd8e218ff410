// The viewer's frame loop. Each frame: events → camera and panel edits (marked dirty on the session); when the
// worker's batch of passes is done, show it, apply the edits (re-upload, reset) and start the next batch sized
// to the frame budget; draw the image and the panels. Timing lines for the closing stats.
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
#include <ctime>
#include <filesystem>

#include "camera_controller.h"
#include "display.h"
#include "image/image_writer.h"
#include "panels.h"
#include "render/progressive_render.h"
#include "render/strata_plan.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"
#include "viewer_session.h"
#include "window.h"

namespace trazo {
namespace {

using Clock = std::chrono::steady_clock;

// A batch of passes aims at this wall time: long enough that the per-batch display update is a small share,
// short enough that an edit restarts the image quickly. The window redraws independently of it.
constexpr double kBatchSeconds = 1.0 / 30.0;
constexpr uint32_t kDefaultTargetPasses = 1024;
// While the user moves the camera or edits (and for the very first image), passes that would take longer than
// this run at 1/2, 1/4 or 1/8 of the size, so the image follows the mouse; full size resumes kPreviewHold
// seconds after the last edit. Screenshots and --frames always use the full size.
constexpr double kPreviewPassSeconds = 1.0 / 20.0;
constexpr double kPreviewHoldSeconds = 0.25;

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

void copyString(char* dst, size_t size, const std::string& src) { std::snprintf(dst, size, "%s", src.c_str()); }

// trazo-YYYYMMDD-HHMMSS.png, with -2, -3… when that file exists already.
std::string timestampedName(const char* extension) {
    const std::time_t now = std::time(nullptr);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
    std::string name = std::string("trazo-") + stamp + extension;
    for (int i = 2; std::filesystem::exists(name); ++i) name = std::string("trazo-") + stamp + "-" + std::to_string(i) + extension;
    return name;
}

std::string editedScenePath(const std::string& scenePath) {
    const std::filesystem::path p(scenePath);
    return (p.parent_path() / (p.stem().string() + "-edited.scene")).string();
}

// The window's starting size: the image's, kept on a usual screen and at least 640×480 (the panel needs room;
// a small image is shown enlarged).
void initialWindowSize(uint32_t width, uint32_t height, int& w, int& h) {
    const double scale = std::clamp(std::min(640.0 / width, 480.0 / height), 1.0, 8.0);
    const double shrink = std::min({1.0, 1600.0 / (width * scale), 1000.0 / (height * scale)});
    w = std::max(int(width * scale * shrink), 320);
    h = std::max(int(height * scale * shrink), 240);
}

bool saveImage(ViewerSession& session, const std::string& path, std::string& message) {
    std::string error;
    if (!writeImage(path, int(session.width()), int(session.height()), session.image(), error)) {
        message = error;
        return false;
    }
    message = "saved " + path + " (" + std::to_string(session.passes()) + " passes)";
    return true;
}

class ViewerApp {
public:
    ViewerApp(const ViewerOptions& options, Window& window, ViewerSession& session, Clock::time_point start)
        : options_(options), window_(window), session_(session), start_(start) {
        std::string device;
        cudaBuilt_ = cudaDeviceAvailable(device) || session.backend().name() == "cuda";
        state_.backend = session.backend().name() == "cuda" ? 1 : 0;
        state_.targetPasses = options.frames ? int(*options.frames)
                                             : int(std::max(kDefaultTargetPasses, session.cyclePasses()));
        autoName_ = options.screenshot.empty() ? timestampedName(".png") : "";
        copyString(state_.screenshotPath, sizeof state_.screenshotPath,
                   options.screenshot.empty() ? autoName_ : options.screenshot);
        copyString(state_.scenePath, sizeof state_.scenePath, editedScenePath(options.scenePath));
        session_.setOnBatchDone(&Window::wake);
        // Larger blocks while a pass still fits the batch budget, unless --blocks fixes them; --frames keeps one
        // stratum per pass, so its image is `--render --blocks 1 --spp N`.
        if (options.blocks) session_.setBlocks(*options.blocks, 0.0);
        else if (!options.frames) session_.setBlocks(StrataBlocks::ones(), kBatchSeconds);
    }

    int run(Display& display) {
        int status = 0;
        auto lastFrame = Clock::now();
        while (!window_.shouldClose()) {
            const bool running = session_.busy();
            const bool finished = state_.targetPasses > 0 && session_.samples() >= double(state_.targetPasses) &&
                                  session_.dirty() == kDirtyNone && !screenshotPending_;
            // Woken early by input or by the batch's end (Window::wake); ImGui gets a few frames to settle.
            if (running || (finished && session_.generation() == shownGeneration_)) {
                window_.waitEvents(settleFrames_ > 0 ? 1.0 / 60.0 : 0.5);
            } else {
                window_.pollEvents();
            }
            const auto frameStart = Clock::now();
            const double dt = std::min(std::chrono::duration<double>(frameStart - lastFrame).count(), 0.1);
            lastFrame = frameStart;
            const bool active = window_.takeActivity();
            if (handleInput(dt) || active) settleFrames_ = 3;

            bool imageChanged = false;
            if (!session_.busy()) {
                // After a reset the last image stays up until the first new passes are done (no black flash).
                if (session_.generation() != shownGeneration_ && session_.passes() > 0) {
                    display.update(session_.backend(), session_.width(), session_.height());
                    shownGeneration_ = session_.generation();
                    imageChanged = true;
                    imageShown_ = true;
                    if (session_.previewDivisor() == 1) fullImageShown_ = true;
                }
                if (options_.frames && session_.passes() >= *options_.frames && session_.dirty() == kDirtyNone) {
                    status = finishAutomation();
                    break;
                }
                if (screenshotPending_ && session_.dirty() == kDirtyNone && session_.passes() > 0 &&
                    session_.previewDivisor() == 1)
                    takeScreenshot();
                if (!options_.frames) choosePreview();
                const uint32_t target = state_.targetPasses > 0 ? uint32_t(state_.targetPasses) : kMaxProgressivePasses;
                if (session_.dirty() != kDirtyNone) session_.applyEdits();
                if (session_.samples() < double(target)) {
                    // The target counts one-stratum passes; a pass of a grown segment stands for several.
                    const double left = (double(target) - session_.samples()) / session_.blocksWeight();
                    const double budget = session_.passesForBudget(kBatchSeconds);
                    session_.startPasses(uint32_t(std::clamp(std::ceil(left), 1.0, budget)));
                    ++batches_;
                }
            }
            // Redraw only when something changed: an idle window leaves the cores to the renderer.
            if (active || imageChanged || settleFrames_ > 0 || frames_ == 0) {
                drawFrame(display);
                if (!active && settleFrames_ > 0) --settleFrames_;
                if (window_.dragging()) {  // the interactive frame rate: frames drawn while a drag goes on
                    const auto now = Clock::now();
                    if (lastDragFrame_ != Clock::time_point{} && secondsSince(lastDragFrame_) < 0.5) {
                        ++dragFrames_;
                        dragSeconds_ += std::chrono::duration<double>(now - lastDragFrame_).count();
                        dragWorkSeconds_ += std::chrono::duration<double>(now - frameStart).count();
                    }
                    lastDragFrame_ = now;
                }
            }
        }
        printStats(display);
        return status;
    }

private:
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

    // Returns true while the camera is flying (keys held send no events, yet the frames must go on).
    bool handleInput(double dt) {
        const ImGuiIO& io = ImGui::GetIO();
        window_.setUiCapture(io.WantCaptureMouse, io.WantCaptureKeyboard);
        const InputEvents e = window_.takeEvents();
        Camera& camera = session_.scene().camera;
        DirtyFlags dirty = kDirtyNone;
        bool flying = false;
        if (e.orbitX != 0 || e.orbitY != 0) {
            controller_.orbit(camera, e.orbitX, e.orbitY);
            dirty |= kDirtyCamera;
        }
        if (e.panX != 0 || e.panY != 0) {
            int fbw, fbh;
            window_.framebufferSize(fbw, fbh);
            controller_.pan(camera, e.panX, e.panY,
                            fitImage(fbw, fbh, session_.renderWidth(), session_.renderHeight()).height);
            dirty |= kDirtyCamera;
        }
        if (e.scroll != 0) {
            controller_.dolly(camera, e.scroll);
            dirty |= kDirtyCamera;
        }
        for (const InputEvents::Key& k : e.keys) {
            const bool ctrl = k.mods & GLFW_MOD_CONTROL;
            if (k.key == GLFW_KEY_F && !ctrl) {
                controller_.frame(camera, sceneBounds(session_.arrays()));
                dirty |= kDirtyCamera;
            } else if (k.key == GLFW_KEY_R && !ctrl) {
                controller_.reset(camera, session_.fileScene().camera);
                dirty |= kDirtyCamera;
            } else if ((k.key == GLFW_KEY_P && !ctrl) || k.key == GLFW_KEY_F12) {
                screenshotPending_ = true;
            } else if (k.key == GLFW_KEY_S && ctrl) {
                saveScene();
            } else if (k.key == GLFW_KEY_Q && ctrl) {
                window_.requestClose();
            }
        }
        // Fly while WASD/QE are held (not with Ctrl: Ctrl+S saves).
        if (!window_.keyDown(GLFW_KEY_LEFT_CONTROL) && !window_.keyDown(GLFW_KEY_RIGHT_CONTROL)) {
            const float forward = float(window_.keyDown(GLFW_KEY_W)) - float(window_.keyDown(GLFW_KEY_S));
            const float right = float(window_.keyDown(GLFW_KEY_D)) - float(window_.keyDown(GLFW_KEY_A));
            const float up = float(window_.keyDown(GLFW_KEY_E)) - float(window_.keyDown(GLFW_KEY_Q));
            if (forward != 0 || right != 0 || up != 0) {
                controller_.fly(camera, forward, right, up, float(dt));
                dirty |= kDirtyCamera;
                flying = true;
            }
        }
        session_.markDirty(dirty);
        if (dirty) lastEdit_ = Clock::now();
        return flying;
    }

    RenderInfo renderInfo(const Display& display) {
        RenderInfo info;
        info.backend = session_.backend().name();
        info.device = session_.backend().deviceName();
        info.displayPath = displayPathName(display.path());
        if (!display.interopFailure().empty() && display.path() == DisplayPath::Host && info.backend == "cuda")
            info.displayPath += " (interop: " + display.interopFailure() + ")";
        info.cudaBuilt = cudaBuilt_;
        info.width = session_.renderWidth();
        info.height = session_.renderHeight();
        if (session_.previewDivisor() > 1) info.displayPath += ", preview at 1/" + std::to_string(session_.previewDivisor());
        info.passes = session_.passes();
        info.cyclePasses = session_.cyclePasses();
        info.samples = session_.samples();
        info.blocks = describeBlocks(session_.blocks());
        info.elapsedSeconds = session_.renderSeconds();
        if (info.elapsedSeconds > 0) {
            info.samplesPerSecond = info.samples * info.width * info.height / info.elapsedSeconds;
            info.mraysPerSecond = double(session_.rays()) / info.elapsedSeconds * 1e-6;
        }
        info.unsupported = session_.unsupported();
        return info;
    }

    void drawFrame(Display& display) {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        const PanelActions actions = drawPanels(session_.scene(), state_, renderInfo(display));
        apply(actions);
        ImGui::Render();

        int fbw, fbh;
        window_.framebufferSize(fbw, fbh);
        glViewport(0, 0, fbw, fbh);
        glClearColor(0.11f, 0.11f, 0.12f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        display.draw(fbw, fbh, state_.tone);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        window_.swapBuffers();
        ++frames_;
        // On screen once swapped.
        if (imageShown_ && firstImageSeconds_ < 0) firstImageSeconds_ = secondsSince(start_);
        if (fullImageShown_ && fullImageSeconds_ < 0) fullImageSeconds_ = secondsSince(start_);
        if (state_.sizeFollowsWindow && fbw > 0 && fbh > 0) {
            // Render at the window's size: the accumulation (and the display) are reallocated when it changes.
            SceneSettings& s = session_.scene().settings;
            if (s.renderWidth != fbw || s.renderHeight != fbh) {
                s.renderWidth = std::min(fbw, kMaxRenderSize);
                s.renderHeight = std::min(fbh, kMaxRenderSize);
                session_.setRenderSize(uint32_t(s.renderWidth), uint32_t(s.renderHeight));
                session_.markDirty(kDirtyCamera);
            }
        }
    }

    void apply(const PanelActions& a) {
        Camera& camera = session_.scene().camera;
        DirtyFlags dirty = a.dirty;
        if (a.frameScene) controller_.frame(camera, sceneBounds(session_.arrays()));
        if (a.resetCamera) controller_.reset(camera, session_.fileScene().camera);
        if (a.frameScene || a.resetCamera || a.restart) dirty |= kDirtyCamera;
        if (dirty) lastEdit_ = Clock::now();
        if (dirty & kDirtySize)
            session_.setRenderSize(uint32_t(session_.scene().settings.renderWidth),
                                   uint32_t(session_.scene().settings.renderHeight));
        session_.markDirty(dirty);
        if (a.switchBackend) {
            std::string why;
            const BackendChoice choice = state_.backend == 1 ? BackendChoice::Cuda : BackendChoice::Cpu;
            auto backend = createBackendFor(session_.arrays(), choice, options_.threads, why);
            if (backend) {
                session_.replaceBackend(std::move(backend));
                state_.status = "now rendering on " + session_.backend().name();
            } else {
                state_.backend = session_.backend().name() == "cuda" ? 1 : 0;
                state_.status = "cannot use CUDA: " + why;
            }
        }
        if (a.screenshot) screenshotPending_ = true;
        if (a.newScreenshotName) {
            const std::string extension = std::filesystem::path(state_.screenshotPath).extension().string();
            autoName_ = timestampedName(extension.empty() ? ".png" : extension.c_str());
            copyString(state_.screenshotPath, sizeof state_.screenshotPath, autoName_);
        }
        if (a.saveScene) saveScene();
    }

    void takeScreenshot() {
        screenshotPending_ = false;
        const std::string path = state_.screenshotPath;
        saveImage(session_, path, state_.status);
        std::fprintf(stderr, "trazo: %s\n", state_.status.c_str());
        // A default name is used once; the next screenshot gets a fresh one (a typed name is reused).
        if (!autoName_.empty() && path == autoName_) {
            autoName_ = timestampedName(std::filesystem::path(path).extension().string().c_str());
            copyString(state_.screenshotPath, sizeof state_.screenshotPath, autoName_);
        }
    }

    void saveScene() {
        std::string error;
        const std::string path = state_.scenePath;
        state_.status = writeSceneFile(session_.scene(), path, error) ? "saved scene " + path : error;
        std::fprintf(stderr, "trazo: %s\n", state_.status.c_str());
    }

    int finishAutomation() {
        if (options_.screenshot.empty()) return 0;
        std::string message;
        if (!saveImage(session_, options_.screenshot, message)) {
            std::fprintf(stderr, "trazo: %s\n", message.c_str());
            return 1;
        }
        return 0;
    }

    void printStats(const Display& display) {
        if (options_.quiet) return;
        session_.waitIdle();
        const double total = secondsSince(start_);
        const double perPass = session_.passes() ? session_.renderSeconds() / session_.passes() : 0.0;
        std::fprintf(stderr,
                     "trazo: viewer %ux%u on %s (%s), display through %s: first image after %.3f s (full size after "
                     "%.3f s); %.2f s open, %llu frames drawn; while dragging %.1f fps (%llu frames, %.1f ms of work "
                     "each); %llu batches; %u passes since the last reset (%.3f s/pass, %.2f Mrays/s)\n",
                     session_.renderWidth(), session_.renderHeight(), session_.backend().name().c_str(),
                     session_.backend().deviceName().c_str(), displayPathName(display.path()), firstImageSeconds_,
                     fullImageSeconds_, total, (unsigned long long)frames_,
                     dragSeconds_ > 0 ? double(dragFrames_) / dragSeconds_ : 0.0, (unsigned long long)dragFrames_,
                     dragFrames_ ? 1e3 * dragWorkSeconds_ / double(dragFrames_) : 0.0, (unsigned long long)batches_,
                     session_.passes(), perPass,
                     session_.renderSeconds() > 0 ? double(session_.rays()) / session_.renderSeconds() * 1e-6 : 0.0);
    }

    const ViewerOptions& options_;
    Window& window_;
    ViewerSession& session_;
    Clock::time_point start_;
    CameraController controller_;
    PanelState state_;
    bool cudaBuilt_ = false;
    std::string autoName_;  // the timestamped default in the Image field, while the user keeps it
    bool screenshotPending_ = false;
    bool imageShown_ = false, fullImageShown_ = false;
    uint64_t shownGeneration_ = ~uint64_t(0);
    uint64_t frames_ = 0, batches_ = 0;
    int settleFrames_ = 0;
    double firstImageSeconds_ = -1.0, fullImageSeconds_ = -1.0;
    Clock::time_point lastEdit_{};
    uint64_t dragFrames_ = 0;  // frames drawn during drags, the time between them, and their own work
    double dragSeconds_ = 0.0, dragWorkSeconds_ = 0.0;
    Clock::time_point lastDragFrame_{};
};

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
    int windowWidth, windowHeight;
    initialWindowSize(width, height, windowWidth, windowHeight);

    std::string error;
    std::unique_ptr<Window> window = Window::open(
        "trazo — " + std::filesystem::path(options.scenePath).filename().string(), windowWidth, windowHeight, error);
    if (!window) {
        std::fprintf(stderr, "trazo: cannot open the viewer: %s; render without a window with `trazo --render %s -o image.png`\n",
                     error.c_str(), options.scenePath.c_str());
        return 1;
    }

    int status = 0;
    try {
        std::string why;
        std::unique_ptr<Backend> backend = createBackend(options.backend, options.threads, why);
        if (!backend) {
            std::fprintf(stderr, "trazo: cannot use the CUDA backend: %s\n", why.c_str());
            return 1;
        }
        if (!options.quiet)
            std::fprintf(stderr, "trazo: viewer on %s (%s)%s%s; GL %s\n", backend->name().c_str(),
                         backend->deviceName().c_str(), why.empty() ? "" : "; CUDA not used: ", why.c_str(),
                         reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
        Display display;
        if (!display.init(error)) {
            std::fprintf(stderr, "trazo: cannot open the viewer: %s; render without a window with `trazo --render %s`\n",
                         error.c_str(), options.scenePath.c_str());
            return 1;
        }
        ViewerSession session(std::move(scene), std::move(backend), options.seed, width, height);
        if (!session.unsupported().empty() && !options.quiet) {
            std::string list;
            for (const std::string& s : session.unsupported()) list += (list.empty() ? "" : "; ") + s;
            std::fprintf(stderr, "%s: warning: rendering without what this version cannot draw yet: %s\n",
                         options.scenePath.c_str(), list.c_str());
        }

        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
        ImGui::StyleColorsDark();
        ImGui_ImplGlfw_InitForOpenGL(window->handle(), true);  // chains to the window's own callbacks
        ImGui_ImplOpenGL3_Init("#version 330 core");
        {
            ViewerApp app(options, *window, session, start);
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
