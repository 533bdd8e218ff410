// Window: the GLFW window with its OpenGL 3.3 core context (loaded by glad), and the mouse and keys turned
// into camera gestures. Drags that start over an ImGui panel stay with the panel.
#pragma once

#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace trazo {

// What the user did since the last takeEvents().
struct InputEvents {
    float orbitX = 0, orbitY = 0;  // left drag, pixels
    float panX = 0, panY = 0;      // middle or shift+left drag, pixels
    float scroll = 0;              // wheel notches, forward > 0
    struct Key {
        int key;   // GLFW_KEY_*
        int mods;  // GLFW_MOD_*
    };
    std::vector<Key> keys;  // presses, in order
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
    bool keyDown(int key) const;
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
