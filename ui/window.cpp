// Window: GLFW set-up, input callbacks and the key bindings. The callbacks are installed before ImGui's GLFW
// backend, which chains to them, so both see every event.
#include "window.h"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace trazo {
namespace {

std::string& lastGlfwError() {
    static std::string message;  // GLFW reports errors through a C callback with no user pointer
    return message;
}

void glfwErrorCallback(int code, const char* description) {
    lastGlfwError() = "GLFW error " + std::to_string(code) + ": " + (description ? description : "");
}

Window* self(GLFWwindow* w) { return static_cast<Window*>(glfwGetWindowUserPointer(w)); }

// The key bindings (README's key list); false for a key that is no command.
bool commandForKey(int key, int mods, ViewerCommand& command) {
    const bool ctrl = mods & GLFW_MOD_CONTROL;
    if (key == GLFW_KEY_F && !ctrl) command = ViewerCommand::FrameScene;
    else if (key == GLFW_KEY_R && !ctrl) command = ViewerCommand::ResetCamera;
    else if ((key == GLFW_KEY_P && !ctrl) || key == GLFW_KEY_F12) command = ViewerCommand::Screenshot;
    else if (key == GLFW_KEY_S && ctrl) command = ViewerCommand::SaveScene;
    else if (key == GLFW_KEY_Q && ctrl) command = ViewerCommand::Quit;
    else return false;
    return true;
}

}  // namespace

std::unique_ptr<Window> Window::open(const std::string& title, int width, int height, std::string& error) {
    glfwSetErrorCallback(glfwErrorCallback);
    lastGlfwError().clear();
    if (!glfwInit()) {
        error = "no display (" + (lastGlfwError().empty() ? std::string("glfwInit failed") : lastGlfwError()) + ")";
        return nullptr;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window) {
        error = "no OpenGL 3.3 core context (" + lastGlfwError() + ")";
        glfwTerminate();
        return nullptr;
    }
    glfwMakeContextCurrent(window);
    const int version = gladLoadGL(glfwGetProcAddress);
    if (!version || GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33) {
        error = "OpenGL 3.3 could not be loaded";
        glfwDestroyWindow(window);
        glfwTerminate();
        return nullptr;
    }
    glfwSwapInterval(1);
    std::unique_ptr<Window> w(new Window(window));
    glfwSetWindowUserPointer(window, w.get());
    glfwSetMouseButtonCallback(window, [](GLFWwindow* g, int b, int a, int m) { self(g)->onMouseButton(b, a, m); });
    glfwSetCursorPosCallback(window, [](GLFWwindow* g, double x, double y) { self(g)->onCursor(x, y); });
    glfwSetScrollCallback(window, [](GLFWwindow* g, double, double dy) { self(g)->onScroll(dy); });
    glfwSetKeyCallback(window, [](GLFWwindow* g, int k, int, int a, int m) { self(g)->onKey(k, a, m); });
    glfwSetCharCallback(window, [](GLFWwindow* g, unsigned) { self(g)->onOtherEvent(); });
    glfwSetCursorEnterCallback(window, [](GLFWwindow* g, int) { self(g)->onOtherEvent(); });
    glfwSetWindowFocusCallback(window, [](GLFWwindow* g, int) { self(g)->onOtherEvent(); });
    glfwSetFramebufferSizeCallback(window, [](GLFWwindow* g, int, int) { self(g)->onOtherEvent(); });
    glfwSetWindowRefreshCallback(window, [](GLFWwindow* g) { self(g)->onOtherEvent(); });
    return w;
}

Window::Window(GLFWwindow* window) : window_(window) { glfwGetCursorPos(window_, &cursorX_, &cursorY_); }

Window::~Window() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_); }
void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void Window::setUiCapture(bool mouse, bool keyboard) {
    uiMouse_ = mouse;
    uiKeyboard_ = keyboard;
}

InputEvents Window::takeEvents() {
    InputEvents out = std::move(events_);
    events_ = InputEvents{};
    return out;
}

bool Window::takeActivity() {
    const bool active = activity_;
    activity_ = false;
    return active;
}

bool Window::keyDown(int key) const { return !uiKeyboard_ && glfwGetKey(window_, key) == GLFW_PRESS; }

FlyKeys Window::flyKeys() const {
    if (keyDown(GLFW_KEY_LEFT_CONTROL) || keyDown(GLFW_KEY_RIGHT_CONTROL)) return {};
    FlyKeys fly;
    fly.forward = float(keyDown(GLFW_KEY_W)) - float(keyDown(GLFW_KEY_S));
    fly.right = float(keyDown(GLFW_KEY_D)) - float(keyDown(GLFW_KEY_A));
    fly.up = float(keyDown(GLFW_KEY_E)) - float(keyDown(GLFW_KEY_Q));
    return fly;
}
void Window::framebufferSize(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }
void Window::pollEvents() { glfwPollEvents(); }
void Window::waitEvents(double timeoutSeconds) { glfwWaitEventsTimeout(timeoutSeconds); }
void Window::swapBuffers() { glfwSwapBuffers(window_); }
void Window::wake() { glfwPostEmptyEvent(); }

void Window::onMouseButton(int button, int action, int mods) {
    activity_ = true;
    if (action == GLFW_PRESS && drag_ == Drag::None && !uiMouse_) {
        if (button == GLFW_MOUSE_BUTTON_MIDDLE || (button == GLFW_MOUSE_BUTTON_LEFT && (mods & GLFW_MOD_SHIFT))) {
            drag_ = Drag::Pan;
        } else if (button == GLFW_MOUSE_BUTTON_LEFT) {
            drag_ = Drag::Orbit;
        }
        if (drag_ != Drag::None) dragButton_ = button;
        glfwGetCursorPos(window_, &cursorX_, &cursorY_);
    } else if (action == GLFW_RELEASE && button == dragButton_) {
        drag_ = Drag::None;
        dragButton_ = -1;
    }
}

void Window::onCursor(double x, double y) {
    activity_ = true;
    const float dx = float(x - cursorX_), dy = float(y - cursorY_);
    cursorX_ = x;
    cursorY_ = y;
    if (drag_ == Drag::Orbit) {
        events_.orbitX += dx;
        events_.orbitY += dy;
    } else if (drag_ == Drag::Pan) {
        events_.panX += dx;
        events_.panY += dy;
    }
}

void Window::onScroll(double dy) {
    activity_ = true;
    if (!uiMouse_) events_.scroll += float(dy);
}

void Window::onKey(int key, int action, int mods) {
    activity_ = true;
    ViewerCommand command;
    if (action == GLFW_PRESS && !uiKeyboard_ && commandForKey(key, mods, command)) events_.commands.push_back(command);
}

}  // namespace trazo
