// Window: the GLFW window with its OpenGL 3.3 core context (loaded by glad), and the mouse and keys turned
// into camera gestures and viewer commands. Drags that start over an ImGui panel stay with the panel.
#pragma once

#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace trazo {

// What a key press asks of the viewer (the bindings: README's key list). The panels' buttons ask the same.
enum class ViewerCommand { FrameScene, ResetCamera, Screenshot, SaveScene, Quit };

// What the user did since the last takeEvents().
struct InputEvents {
    float orbitX = 0, orbitY = 0;  // left drag, pixels
    float panX = 0, panY = 0;      // middle or shift+left drag, pixels
    float scroll = 0;              // wheel notches, forward > 0
    std::vector<ViewerCommand> commands;  // in the order their keys were pressed
};

// The fly keys held now, each axis -1, 0 or 1 (W/S forward, D/A right, E/Q up).
struct FlyKeys {
    float forward = 0, right = 0, up = 0;
    bool moving() const { return forward != 0 || right != 0 || up != 0; }
};

class Window {
public:
    // Opens the window (width × height screen pixels) and makes its context current. Null, with the reason in
    // `error`, when there is no display or no OpenGL 3.3 core context; never aborts.
    static std::unique_ptr<Window> open(const std::string& title, int width, int height, std::string& error);
    ~Window();  // destroys the window and ends GLFW
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    bool shouldClose() const;
    void requestClose();
    // Whether ImGui wants the mouse and the keyboard this frame (gestures and keys are then left to it).
    void setUiCapture(bool mouse, bool keyboard);
    InputEvents takeEvents();
    // True when any window event (input, resize, expose, focus) arrived since the last call: the frame loop
    // redraws only then, or when the image changed, so the UI leaves the cores to the renderer.
    bool takeActivity();
    // None while Ctrl is held (Ctrl+S saves, Ctrl+Q quits) or while ImGui has the keyboard.
    FlyKeys flyKeys() const;
    bool dragging() const { return drag_ != Drag::None; }
    void framebufferSize(int& width, int& height) const;
    void pollEvents();
    void waitEvents(double timeoutSeconds);
    void swapBuffers();
    // Wakes waitEvents() from any thread (a finished batch of passes).
    static void wake();

    // GLFW callbacks (public for the C trampolines).
    void onMouseButton(int button, int action, int mods);
    void onCursor(double x, double y);
    void onScroll(double dy);
    void onKey(int key, int action, int mods);
    void onOtherEvent() { activity_ = true; }

private:
    explicit Window(GLFWwindow* window);
    bool keyDown(int key) const;

    enum class Drag { None, Orbit, Pan };
    GLFWwindow* window_;
    bool uiMouse_ = false, uiKeyboard_ = false;
    Drag drag_ = Drag::None;
    int dragButton_ = -1;
    double cursorX_ = 0, cursorY_ = 0;
    InputEvents events_;
    bool activity_ = true;
};

}  // namespace trazo
