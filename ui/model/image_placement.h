// ImagePlacement: where the image sits inside its area of the window: fitted (the whole image, as large as the
// area allows), or at a zoom with a pan (1:1 is zoom 1: one image pixel per framebuffer pixel). Pure math in
// framebuffer pixels with the origin at the top-left (the display turns it into GL's bottom-left); the window's
// clicks are mapped back to image pixels through it. No GL.
#pragma once

#include <cstdint>
#include <optional>

namespace trazo {

// A rectangle in framebuffer pixels, x, y from the top-left.
struct ImageRect {
    float x = 0, y = 0, width = 0, height = 0;
    bool contains(float px, float py) const { return px >= x && py >= y && px < x + width && py < y + height; }
};

// The largest rectangle of the image's aspect ratio centred in `area`, at whole pixels.
ImageRect fitImage(const ImageRect& area, uint32_t imageWidth, uint32_t imageHeight);

// A point of the image in its own pixels: (0, 0) the top-left corner, (width, height) the bottom-right.
struct ImagePoint {
    float x = 0, y = 0;
};

class ImagePlacement {
public:
    static constexpr float kMinZoom = 1.0f / 32.0f, kMaxZoom = 64.0f;

    bool fitted() const { return fitted_; }
    // Framebuffer pixels per image pixel as shown now (the fit's scale while fitted).
    float scale(const ImageRect& area, uint32_t imageWidth, uint32_t imageHeight) const;

    void fit() { fitted_ = true; }
    // 1:1, centred in the area.
    void actualPixels();
    // Zooms by `factor` about the framebuffer point (px, py): the image point under it stays under it. From the
    // fit, the zoom starts at the fit's scale.
    void zoomBy(float factor, float px, float py, const ImageRect& area, uint32_t imageWidth, uint32_t imageHeight);
    // Moves the image by (dx, dy) framebuffer pixels (leaves the fit where it was).
    void panBy(float dx, float dy, const ImageRect& area, uint32_t imageWidth, uint32_t imageHeight);

    // The image's rectangle: its top-left corner at whole pixels, so that at 1:1 each image pixel is one
    // framebuffer pixel.
    ImageRect rect(const ImageRect& area, uint32_t imageWidth, uint32_t imageHeight) const;
    // The image point under the framebuffer point (px, py), also beyond the image's edges (a move's cursor).
    ImagePoint toImage(float px, float py, const ImageRect& area, uint32_t imageWidth, uint32_t imageHeight) const;
    // The same, but none outside the image or its area (a click).
    std::optional<ImagePoint> imagePoint(float px, float py, const ImageRect& area, uint32_t imageWidth,
                                         uint32_t imageHeight) const;

private:
    void leaveFit(const ImageRect& area, uint32_t imageWidth, uint32_t imageHeight);

    bool fitted_ = true;
    float zoom_ = 1.0f;
    float panX_ = 0, panY_ = 0;  // the image centre's offset from the area's centre, framebuffer pixels
};

}  // namespace trazo
