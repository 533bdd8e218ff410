// The window's layout: the side panel on the left, the menu bar on top, the image's area the rest (never under
// a panel). Sizes of the panel and the menu bar are in window (screen) coordinates, as ImGui and the mouse have
// them; the image's area is in framebuffer pixels, which differ on HiDPI screens. No GL.
#pragma once

#include <cstdint>

#include "model/image_placement.h"

namespace trazo {

constexpr float kPanelWidth = 380.0f;  // the side panel's opening width in UI points (× the content scale)
constexpr float kMinPanelWidth = 240.0f, kMaxPanelShare = 0.7f;  // its edge drags between these
constexpr int kMinWindowWidth = 640, kMinWindowHeight = 480;     // screen coordinates

// The window's opening size in screen coordinates: the image at 1:1 (width × height framebuffer pixels, i.e.
// / framebufferScale screen coordinates) beside the panel and under the menu bar, at least the minimum, at most
// 90 % of the screen (decorations and task bars).
void initialWindowSize(uint32_t imageWidth, uint32_t imageHeight, float panelWidth, float menuHeight,
                       float framebufferScale, int screenWidth, int screenHeight, int& width, int& height);

// The image's area: right of the panel and below the menu bar, in framebuffer pixels from the top-left.
ImageRect imageArea(int windowWidth, int windowHeight, int framebufferWidth, int framebufferHeight, float panelWidth,
                    float menuHeight);

}  // namespace trazo
