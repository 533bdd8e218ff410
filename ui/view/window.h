// Window: the GLFW window with its OpenGL 3.3 core context (loaded by glad), and the mouse and keys turned
// into gestures (camera, view, clicks, object moves) and viewer commands. Drags that start over an ImGui
// panel stay with the panel. Positions are in window coordinates (ImGui's, the mouse's), from the top-left.
#pragma once

#include <memory>
#include <set>
#include <string>
#include <vector>

#include "view/viewer_command.h"

struct GLFWwindow;

namespace trazo {

struct CursorPoint {
    float x = 0, y = 0;
};

// What the user did since the last takeEvents().
struct InputEvents {
    float orbitX = 0, orbitY = 0;  // left drag, pixels
    float panX = 0, panY = 0;      // middle or shift+left drag, pixels
    float scroll = 0;              // wheel notches, forward > 0 (the dolly; the depth during a move)
    float viewPanX = 0, viewPanY = 0;  // right or space+left drag: the image's view, pixels
    float zoom = 0;                    // Ctrl+wheel notches, about `zoomAt`
    CursorPoint zoomAt;
    std::vector<CursorPoint> clicks;   // left press and release within a few pixels (no orbit)
    bool moveStarted = false, moveEnded = false;  // an Alt+left drag (its moves: the cursor)
    CursorPoint moveStart;
    std::vector<std::string> drops;    // files dropped onto the window
    std::vector<ViewerCommand> commands;  // in the order their keys were pressed
};

// The fly keys held now, each axis -1, 0 or 1 (W/S forward, D/A right, E/Q up).
struct FlyKeys {
    float forward = 0, right = 0, up = 0;
    bool moving() const { return forward != 0 || right != 0 || up != 0; }
};

// The screen the window opens on: the primary monitor's mode (screen coordinates) and its content scale.
struct ScreenInfo {
    int width = 0, height = 0;
    float contentScale = 1.0f;
};

class Window {
public:
    // Opens the window, hidden (show() sizes and shows it), and makes its context current. Null, with the reason
    // in `error`, when there is no display or no OpenGL 3.3 core context; never aborts.
    static std::unique_ptr<Window> open(const std::string& title, std::string& error);
    ~Window();  // destroys the window and ends GLFW
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    ScreenInfo screen() const;
    // Framebuffer pixels per window coordinate (2 on a Retina screen, 1 on X11 and Windows).
    float framebufferScale() const;
    void show(int width, int height);
    void setTitle(const std::string& title);
    bool shouldClose() const;
    void requestClose();
    void cancelClose();  // vetoes the close button (the unsaved-changes question is asked first)
    // Whether ImGui wants the mouse and the keyboard this frame (gestures and keys are then left to it).
    void setUiCapture(bool mouse, bool keyboard);
    // The image's area in window coordinates: the viewer's gestures start only there (a press or a wheel notch
    // elsewhere is the panel's or the menu's, even when it comes in the same poll as the move that got there).
    void setImageArea(float x, float y, float width, float height);
    // During a move the buttons end it (left confirms, right cancels) and the wheel changes its depth.
    void setMoving(bool moving);
    InputEvents takeEvents();
    // True when any window event (input, resize, expose, focus) arrived since the last call: the frame loop
    // redraws only then, or when the image changed, so the UI leaves the cores to the renderer.
    bool takeActivity();
    // Keys pressed with Ctrl, Shift or Alt (Ctrl+S saves, Shift+D duplicates) do not fly, nor any while ImGui
    // has the keyboard.
    FlyKeys flyKeys() const;
    bool dragging() const { return drag_ != Drag::None && drag_ != Drag::Pending; }
    CursorPoint cursor() const { return {float(cursorX_), float(cursorY_)}; }
    void windowSize(int& width, int& height) const;
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
    void onDrop(int count, const char** paths);
    void onOtherEvent() { activity_ = true; }

private:
    explicit Window(GLFWwindow* window);
    bool keyDown(int key) const;
    bool inImageArea(double x, double y) const;
    bool uiHasMouse() const;  // at the cursor now

    // Pending: a left press that is a click until it moves more than a few pixels, then an orbit.
    enum class Drag { None, Pending, Orbit, Pan, ViewPan, Move };
    GLFWwindow* window_;
    bool uiMouse_ = false, uiKeyboard_ = false, moving_ = false;
    bool uiMouseInArea_ = false;  // where the cursor was when ImGui said it wanted the mouse
    float areaX_ = 0, areaY_ = 0, areaWidth_ = 0, areaHeight_ = 0;
    Drag drag_ = Drag::None;
    int dragButton_ = -1;
    double cursorX_ = 0, cursorY_ = 0, pressX_ = 0, pressY_ = 0;
    InputEvents events_;
    std::set<int> commandKeys_;  // pressed with a modifier, not released yet
    bool activity_ = true;
};

}  // namespace trazo
