// Display: shows the accumulation in the window. A pixel-buffer object receives the estimate (sum / count as
// float RGBA): written by the backend through CUDA-GL interop when it can, otherwise filled from the host
// through a mapped pointer. It is copied into a float texture that the display shader (shaders/) tone-maps
// into the window. GL code only; needs the window's context current.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "model/panel_state.h"
#include "model/image_placement.h"

namespace trazo {

enum class DisplayPath { None, Interop, Host };
const char* displayPathName(DisplayPath path);

class Display {
public:
    Display() = default;
    ~Display();
    Display(const Display&) = delete;
    Display& operator=(const Display&) = delete;

    // Compiles the shaders and creates the objects; false with the reason when GL refuses.
    bool init(std::string& error);
    // Brings the backend's current estimate to the screen texture (width × height = the accumulation's size;
    // a new size reallocates). Interop first, unless it failed for this backend before.
    void update(Backend& backend, uint32_t width, uint32_t height);
    // The selection's outline over the image: one byte per pixel (non-zero: outline), width × height of the
    // image, row 0 = top; an empty mask shows none. Only the display sees it, never the accumulation.
    void setOutline(const std::vector<uint8_t>& mask, uint32_t width, uint32_t height);
    // Clears the framebuffer to the viewer's background (also the colour around the image), then draws the image
    // into `rect` (framebuffer pixels from the top-left, ImagePlacement::rect) clipped to `area`.
    void draw(int framebufferWidth, int framebufferHeight, const ImageRect& area, const ImageRect& rect,
              const ToneSettings& tone) const;

    DisplayPath path() const { return path_; }
    const std::string& interopFailure() const { return interopFailure_; }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }

private:
    void allocate(uint32_t width, uint32_t height);
    bool fillFromHost(Backend& backend);

    unsigned program_ = 0, vao_ = 0, texture_ = 0, pbo_ = 0, outline_ = 0;
    int uImageRect_ = -1, uAreaRect_ = -1, uExposure_ = -1, uToneMode_ = -1, uOutside_ = -1, uEstimate_ = -1;
    int uOutline_ = -1, uHasOutline_ = -1;
    bool hasOutline_ = false;
    uint32_t width_ = 0, height_ = 0;
    DisplayPath path_ = DisplayPath::None;
    const Backend* interopFailedFor_ = nullptr;
    std::string interopFailure_;
    std::vector<AccumPixel> accum_;  // host path scratch
};

}  // namespace trazo
