// Window: GLFW set-up, input callbacks and the key bindings. The callbacks are installed before ImGui's GLFW
// backend, which chains to them, so both see every event.
#include "view/window.h"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>

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
    const bool ctrl = mods & GLFW_MOD_CONTROL, shift = mods & GLFW_MOD_SHIFT;
    if (ctrl) {
        switch (key) {
            case GLFW_KEY_S: command = ViewerCommand::SaveScene; return true;
            case GLFW_KEY_Q: command = ViewerCommand::Quit; return true;
            case GLFW_KEY_Z: command = shift ? ViewerCommand::Redo : ViewerCommand::Undo; return true;
            case GLFW_KEY_Y: command = ViewerCommand::Redo; return true;
            case GLFW_KEY_D: command = ViewerCommand::Duplicate; return true;
            case GLFW_KEY_O: command = ViewerCommand::OpenPrompt; return true;
            default: return false;
        }
    }
    if (shift && key == GLFW_KEY_D) {
        command = ViewerCommand::Duplicate;
        return true;
    }
    if (shift && key == GLFW_KEY_A) {
        command = ViewerCommand::AddSphere;
        return true;
    }
    if (shift && key == GLFW_KEY_F) {
        command = ViewerCommand::FocusPick;
        return true;
    }
    switch (key) {
        case GLFW_KEY_F: command = ViewerCommand::FrameScene; return true;
        case GLFW_KEY_R: command = ViewerCommand::ResetCamera; return true;
        case GLFW_KEY_P:
        case GLFW_KEY_F12: command = ViewerCommand::Screenshot; return true;
        case GLFW_KEY_0:
        case GLFW_KEY_HOME: command = ViewerCommand::FitView; return true;
        case GLFW_KEY_1: command = ViewerCommand::ActualPixels; return true;
        case GLFW_KEY_EQUAL:
        case GLFW_KEY_KP_ADD: command = ViewerCommand::ZoomIn; return true;
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT: command = ViewerCommand::ZoomOut; return true;
        case GLFW_KEY_G: command = ViewerCommand::Grab; return true;
        case GLFW_KEY_ENTER:
        case GLFW_KEY_KP_ENTER: command = ViewerCommand::Confirm; return true;
        case GLFW_KEY_ESCAPE: command = ViewerCommand::Cancel; return true;
        case GLFW_KEY_DELETE:
        case GLFW_KEY_X: command = ViewerCommand::Delete; return true;
        default: return false;
    }
}

// A press that moves less than this (window coordinates) before its release is a click, not a drag.
constexpr double kClickSlop = 4.0;

}  // namespace

std::unique_ptr<Window> Window::open(const std::string& title, std::string& error) {
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
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);  // shown at its size once the layout knows the scales
    GLFWwindow* window = glfwCreateWindow(640, 480, title.c_str(), nullptr, nullptr);
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
    glfwSetDropCallback(window, [](GLFWwindow* g, int n, const char** p) { self(g)->onDrop(n, p); });
    glfwSetCharCallback(window, [](GLFWwindow* g, unsigned) { self(g)->onOtherEvent(); });
    glfwSetCursorEnterCallback(window, [](GLFWwindow* g, int) { self(g)->onOtherEvent(); });
    glfwSetWindowFocusCallback(window, [](GLFWwindow* g, int) { self(g)->onOtherEvent(); });
    glfwSetFramebufferSizeCallback(window, [](GLFWwindow* g, int, int) { self(g)->onOtherEvent(); });
    glfwSetWindowRefreshCallback(window, [](GLFWwindow* g) { self(g)->onOtherEvent(); });
    glfwSetWindowCloseCallback(window, [](GLFWwindow* g) { self(g)->onOtherEvent(); });
    return w;
}

ScreenInfo Window::screen() const {
    ScreenInfo info;
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
        if (const GLFWvidmode* mode = glfwGetVideoMode(monitor)) {
            info.width = mode->width;
            info.height = mode->height;
        }
    }
    float sx = 1.0f, sy = 1.0f;
    glfwGetWindowContentScale(window_, &sx, &sy);
    info.contentScale = sx > 0 ? sx : 1.0f;
    return info;
}

float Window::framebufferScale() const {
    int w, h, fw, fh;
    glfwGetWindowSize(window_, &w, &h);
    glfwGetFramebufferSize(window_, &fw, &fh);
    return w > 0 && fw > 0 ? float(fw) / float(w) : 1.0f;
}

void Window::show(int width, int height) {
    glfwSetWindowSize(window_, width, height);
    glfwShowWindow(window_);
    activity_ = true;
}

void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

Window::Window(GLFWwindow* window) : window_(window) { glfwGetCursorPos(window_, &cursorX_, &cursorY_); }

Window::~Window() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_); }
void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void Window::cancelClose() { glfwSetWindowShouldClose(window_, GLFW_FALSE); }
void Window::setMoving(bool moving) { moving_ = moving; }

void Window::setUiCapture(bool mouse, bool keyboard) {
    uiMouse_ = mouse;
    uiKeyboard_ = keyboard;
    uiMouseInArea_ = inImageArea(cursorX_, cursorY_);
}

void Window::setImageArea(float x, float y, float width, float height) {
    areaX_ = x;
    areaY_ = y;
    areaWidth_ = width;
    areaHeight_ = height;
}

bool Window::inImageArea(double x, double y) const {
    return x >= areaX_ && y >= areaY_ && x < areaX_ + areaWidth_ && y < areaY_ + areaHeight_;
}

// Outside the image's area the panel and the menu bar have the mouse. Inside, ImGui's word counts only when it
// was said with the cursor inside too (a menu or a question over the image), not about the panel it just left.
bool Window::uiHasMouse() const {
    if (!inImageArea(cursorX_, cursorY_)) return true;
    return uiMouse_ && uiMouseInArea_;
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
    const auto held = [&](int key) { return keyDown(key) && !commandKeys_.count(key); };
    FlyKeys fly;
    fly.forward = float(held(GLFW_KEY_W)) - float(held(GLFW_KEY_S));
    fly.right = float(held(GLFW_KEY_D)) - float(held(GLFW_KEY_A));
    fly.up = float(held(GLFW_KEY_E)) - float(held(GLFW_KEY_Q));
    return fly;
}
void Window::windowSize(int& width, int& height) const { glfwGetWindowSize(window_, &width, &height); }
void Window::framebufferSize(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }
void Window::pollEvents() { glfwPollEvents(); }
void Window::waitEvents(double timeoutSeconds) { glfwWaitEventsTimeout(timeoutSeconds); }
void Window::swapBuffers() { glfwSwapBuffers(window_); }
void Window::wake() { glfwPostEmptyEvent(); }

void Window::onMouseButton(int button, int action, int mods) {
    activity_ = true;
    glfwGetCursorPos(window_, &cursorX_, &cursorY_);
    if (moving_) {  // a move in progress: the buttons end it, nothing else starts
        if (action == GLFW_PRESS && !uiHasMouse() && button == GLFW_MOUSE_BUTTON_LEFT)
            events_.commands.push_back(ViewerCommand::Confirm);
        else if (action == GLFW_PRESS && !uiHasMouse() && button == GLFW_MOUSE_BUTTON_RIGHT)
            events_.commands.push_back(ViewerCommand::Cancel);
        else if (action == GLFW_RELEASE && button == dragButton_ && drag_ == Drag::Move)
            events_.moveEnded = true;
        if (action == GLFW_RELEASE && button == dragButton_) {
            drag_ = Drag::None;
            dragButton_ = -1;
        }
        return;
    }
    if (action == GLFW_PRESS && drag_ == Drag::None && !uiHasMouse()) {
        pressX_ = cursorX_;
        pressY_ = cursorY_;
        const bool left = button == GLFW_MOUSE_BUTTON_LEFT;
        if (button == GLFW_MOUSE_BUTTON_MIDDLE || (left && (mods & GLFW_MOD_SHIFT))) {
            drag_ = Drag::Pan;
        } else if (button == GLFW_MOUSE_BUTTON_RIGHT || (left && keyDown(GLFW_KEY_SPACE))) {
            drag_ = Drag::ViewPan;
        } else if (left && (mods & GLFW_MOD_ALT)) {
            drag_ = Drag::Move;
            events_.moveStarted = true;
            events_.moveStart = cursor();
        } else if (left) {
            drag_ = Drag::Pending;
        }
        if (drag_ != Drag::None) dragButton_ = button;
    } else if (action == GLFW_RELEASE && button == dragButton_) {
        if (drag_ == Drag::Pending) events_.clicks.push_back(cursor());
        if (drag_ == Drag::Move) events_.moveEnded = true;
        drag_ = Drag::None;
        dragButton_ = -1;
    }
}

void Window::onCursor(double x, double y) {
    activity_ = true;
    const float dx = float(x - cursorX_), dy = float(y - cursorY_);
    cursorX_ = x;
    cursorY_ = y;
    if (drag_ == Drag::Pending && std::hypot(x - pressX_, y - pressY_) > kClickSlop) {
        drag_ = Drag::Orbit;  // no longer a click: the orbit takes the whole way from the press
        events_.orbitX += float(x - pressX_);
        events_.orbitY += float(y - pressY_);
    } else if (drag_ == Drag::Orbit) {
        events_.orbitX += dx;
        events_.orbitY += dy;
    } else if (drag_ == Drag::Pan) {
        events_.panX += dx;
        events_.panY += dy;
    } else if (drag_ == Drag::ViewPan) {
        events_.viewPanX += dx;
        events_.viewPanY += dy;
    }
}

void Window::onScroll(double dy) {
    activity_ = true;
    glfwGetCursorPos(window_, &cursorX_, &cursorY_);
    if (uiHasMouse()) return;
    if (!moving_ && (keyDown(GLFW_KEY_LEFT_CONTROL) || keyDown(GLFW_KEY_RIGHT_CONTROL))) {
        events_.zoom += float(dy);
        events_.zoomAt = cursor();
    } else {
        events_.scroll += float(dy);
    }
}

void Window::onKey(int key, int action, int mods) {
    activity_ = true;
    // A key pressed with a modifier (Ctrl+S, Shift+D, Shift+A) is a command until released, never a flight. The
    // event's modifiers, not glfwGetKey's Ctrl: xdotool's Ctrl may come on a key code GLFW does not name.
    if (action == GLFW_PRESS && (mods & (GLFW_MOD_CONTROL | GLFW_MOD_SHIFT | GLFW_MOD_ALT))) commandKeys_.insert(key);
    else if (action == GLFW_RELEASE) commandKeys_.erase(key);
    ViewerCommand command;
    if (action == GLFW_PRESS && !uiKeyboard_ && commandForKey(key, mods, command)) events_.commands.push_back(command);
}

void Window::onDrop(int count, const char** paths) {
    activity_ = true;
    for (int i = 0; i < count; ++i) events_.drops.emplace_back(paths[i]);
}

}  // namespace trazo
