// ImagePlacement: fit, zoom about a point, pan, and the mapping from framebuffer points to image pixels.
#include "model/image_placement.h"

#include <algorithm>
#include <cmath>

namespace trazo {

ImageRect fitImage(const ImageRect& area, uint32_t imageWidth, uint32_t imageHeight) {
    if (area.width <= 0 || area.height <= 0 || imageWidth == 0 || imageHeight == 0) return {area.x, area.y, 0, 0};
    const float scale = std::min(area.width / float(imageWidth), area.height / float(imageHeight));
    ImageRect r;
    r.width = std::floor(float(imageWidth) * scale);
    r.height = std::floor(float(imageHeight) * scale);
    r.x = area.x + std::floor(0.5f * (area.width - r.width));
    r.y = area.y + std::floor(0.5f * (area.height - r.height));
    return r;
}

float ImagePlacement::scale(const ImageRect& area, uint32_t imageWidth, uint32_t imageHeight) const {
    if (!fitted_) return zoom_;
    if (imageWidth == 0 || imageHeight == 0) return 1.0f;
    return fitImage(area, imageWidth, imageHeight).width / float(imageWidth);
}

void ImagePlacement::actualPixels() {
    fitted_ = false;
    zoom_ = 1.0f;
    panX_ = panY_ = 0;
}

void ImagePlacement::leaveFit(const ImageRect& area, uint32_t imageWidth, uint32_t imageHeight) {
    if (!fitted_) return;
    const ImageRect r = fitImage(area, imageWidth, imageHeight);
    zoom_ = std::clamp(imageWidth ? r.width / float(imageWidth) : 1.0f, kMinZoom, kMaxZoom);
    panX_ = r.x + 0.5f * r.width - (area.x + 0.5f * area.width);
    panY_ = r.y + 0.5f * r.height - (area.y + 0.5f * area.height);
    fitted_ = false;
}

void ImagePlacement::zoomBy(float factor, float px, float py, const ImageRect& area, uint32_t imageWidth,
                           uint32_t imageHeight) {
    leaveFit(area, imageWidth, imageHeight);
    const float zoom = std::clamp(zoom_ * factor, kMinZoom, kMaxZoom);
    // The image centre sits at c = areaCentre + pan; a point p keeps its image coordinate when p − c scales
    // with the zoom.
    const float cx = area.x + 0.5f * area.width, cy = area.y + 0.5f * area.height;
    const float ratio = zoom / zoom_;
    panX_ = px - (px - (cx + panX_)) * ratio - cx;
    panY_ = py - (py - (cy + panY_)) * ratio - cy;
    zoom_ = zoom;
}

void ImagePlacement::panBy(float dx, float dy, const ImageRect& area, uint32_t imageWidth, uint32_t imageHeight) {
    leaveFit(area, imageWidth, imageHeight);
    panX_ += dx;
    panY_ += dy;
}

ImageRect ImagePlacement::rect(const ImageRect& area, uint32_t imageWidth, uint32_t imageHeight) const {
    if (fitted_) return fitImage(area, imageWidth, imageHeight);
    ImageRect r;
    r.width = float(imageWidth) * zoom_;
    r.height = float(imageHeight) * zoom_;
    r.x = std::floor(area.x + 0.5f * (area.width - r.width) + panX_);
    r.y = std::floor(area.y + 0.5f * (area.height - r.height) + panY_);
    return r;
}

ImagePoint ImagePlacement::toImage(float px, float py, const ImageRect& area, uint32_t imageWidth,
                                  uint32_t imageHeight) const {
    const ImageRect r = rect(area, imageWidth, imageHeight);
    if (r.width <= 0 || r.height <= 0) return {};
    return ImagePoint{(px - r.x) / r.width * float(imageWidth), (py - r.y) / r.height * float(imageHeight)};
}

std::optional<ImagePoint> ImagePlacement::imagePoint(float px, float py, const ImageRect& area, uint32_t imageWidth,
                                                    uint32_t imageHeight) const {
    const ImageRect r = rect(area, imageWidth, imageHeight);
    if (r.width <= 0 || r.height <= 0 || !r.contains(px, py) || !area.contains(px, py)) return std::nullopt;
    return toImage(px, py, area, imageWidth, imageHeight);
}

}  // namespace trazo
