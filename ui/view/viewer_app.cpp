// runViewer: reads the scene, opens the window, the backend, the display and Dear ImGui, and runs ViewerApp's
// frame loop (viewer_frame_loop.h) until the window closes.
#include "view/viewer_app.h"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cstdio>
#include <filesystem>

#include "image/image_writer.h"
#include "render/render_start.h"
#include "render/strata_plan.h"
#include "scene/scene_reader.h"
#include "view/viewer_frame_loop.h"

namespace trazo {
namespace {

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
    const auto start = ViewerApp::Clock::now();
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
