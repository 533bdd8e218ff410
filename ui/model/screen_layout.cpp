// The window's layout arithmetic: the opening size and the image's area beside the panel.
#include "model/screen_layout.h"

#include <algorithm>
#include <cmath>

namespace trazo {

void initialWindowSize(uint32_t imageWidth, uint32_t imageHeight, float panelWidth, float menuHeight,
                       float framebufferScale, int screenWidth, int screenHeight, int& width, int& height) {
    const float scale = framebufferScale > 0 ? framebufferScale : 1.0f;
    const double wanted[2] = {std::ceil(imageWidth / scale + panelWidth), std::ceil(imageHeight / scale + menuHeight)};
    const int screen[2] = {screenWidth > 0 ? screenWidth : 1600, screenHeight > 0 ? screenHeight : 1000};
    const int least[2] = {kMinWindowWidth, kMinWindowHeight};
    int out[2];
    for (int i = 0; i < 2; ++i) {
        const int most = std::max(int(0.9 * screen[i]), std::min(least[i], screen[i]));
        out[i] = std::clamp(int(wanted[i]), std::min(least[i], most), most);
    }
    width = out[0];
    height = out[1];
}

ImageRect imageArea(int windowWidth, int windowHeight, int framebufferWidth, int framebufferHeight, float panelWidth,
                    float menuHeight) {
    if (windowWidth <= 0 || windowHeight <= 0) return {};
    const float sx = float(framebufferWidth) / float(windowWidth), sy = float(framebufferHeight) / float(windowHeight);
    ImageRect area;
    area.x = std::min(std::round(panelWidth * sx), float(framebufferWidth));
    area.y = std::min(std::round(menuHeight * sy), float(framebufferHeight));
    area.width = float(framebufferWidth) - area.x;
    area.height = float(framebufferHeight) - area.y;
    return area;
}

}  // namespace trazo
