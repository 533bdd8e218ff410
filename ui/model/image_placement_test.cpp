// Tests of the image's placement in its area: the fit, 1:1 at whole pixels, zoom about the cursor (the image
// point under it stays), pan, and framebuffer points mapped back to image pixels.
#include "model/image_placement.h"

#include <gtest/gtest.h>

namespace trazo {
namespace {

const ImageRect kArea{380, 20, 600, 400};  // right of a panel, below a menu bar

TEST(ImagePlacement, FitIsTheLargestCentredRectangleAtWholePixels) {
    const ImageRect r = fitImage(kArea, 300, 100);  // wide: limited by the width, scale 2
    EXPECT_EQ(r.width, 600);
    EXPECT_EQ(r.height, 200);
    EXPECT_EQ(r.x, 380);
    EXPECT_EQ(r.y, 20 + 100);
    const ImageRect t = fitImage(kArea, 100, 300);  // tall: scale 4/3, 133.33 → 133 wide
    EXPECT_EQ(t.width, 133);
    EXPECT_EQ(t.height, 400);
    EXPECT_EQ(t.x, 380 + 233);  // floor((600 − 133) / 2)
    EXPECT_EQ(t.y, 20);
    EXPECT_EQ(fitImage(kArea, 0, 10).width, 0);
    EXPECT_EQ(fitImage({0, 0, 0, 10}, 10, 10).width, 0);
}

TEST(ImagePlacement, ActualPixelsIsOneToOneAndCentred) {
    ImagePlacement v;
    EXPECT_TRUE(v.fitted());
    EXPECT_FLOAT_EQ(v.scale(kArea, 300, 100), 2.0f);
    v.actualPixels();
    EXPECT_FALSE(v.fitted());
    const ImageRect r = v.rect(kArea, 301, 101);  // odd sizes: the corner still at whole pixels
    EXPECT_EQ(r.width, 301);
    EXPECT_EQ(r.height, 101);
    EXPECT_EQ(r.x, 380 + 149);  // floor(380 + 149.5)
    EXPECT_EQ(r.y, 20 + 149);
    EXPECT_EQ(v.scale(kArea, 301, 101), 1.0f);
    v.fit();
    EXPECT_EQ(v.rect(kArea, 301, 101).width, fitImage(kArea, 301, 101).width);
}

TEST(ImagePlacement, ZoomKeepsThePointUnderTheCursor) {
    ImagePlacement v;
    v.actualPixels();
    const float px = 700, py = 150;
    const ImagePoint before = *v.imagePoint(px, py, kArea, 200, 200);
    v.zoomBy(2.0f, px, py, kArea, 200, 200);
    EXPECT_FLOAT_EQ(v.scale(kArea, 200, 200), 2.0f);
    const ImagePoint after = *v.imagePoint(px, py, kArea, 200, 200);
    EXPECT_NEAR(after.x, before.x, 0.5f);  // the rectangle's corner is rounded to whole pixels
    EXPECT_NEAR(after.y, before.y, 0.5f);
    v.zoomBy(1e6f, px, py, kArea, 200, 200);
    EXPECT_EQ(v.scale(kArea, 200, 200), ImagePlacement::kMaxZoom);
}

TEST(ImagePlacement, ZoomFromTheFitStartsAtTheFitScale) {
    ImagePlacement v;
    const ImageRect fit = v.rect(kArea, 300, 100);
    v.zoomBy(1.0f, 500, 200, kArea, 300, 100);  // a zoom by 1 leaves the image where the fit had it
    EXPECT_FALSE(v.fitted());
    const ImageRect r = v.rect(kArea, 300, 100);
    EXPECT_EQ(r.x, fit.x);
    EXPECT_EQ(r.y, fit.y);
    EXPECT_EQ(r.width, fit.width);
}

TEST(ImagePlacement, PanMovesTheImageAndTheMapping) {
    ImagePlacement v;
    v.actualPixels();
    const ImageRect r0 = v.rect(kArea, 100, 100);
    v.panBy(30, -12, kArea, 100, 100);
    const ImageRect r1 = v.rect(kArea, 100, 100);
    EXPECT_EQ(r1.x, r0.x + 30);
    EXPECT_EQ(r1.y, r0.y - 12);
    const ImagePoint p = *v.imagePoint(r1.x + 10.5f, r1.y + 3.25f, kArea, 100, 100);
    EXPECT_FLOAT_EQ(p.x, 10.5f);
    EXPECT_FLOAT_EQ(p.y, 3.25f);
}

TEST(ImagePlacement, PointsOutsideTheImageOrItsAreaMapToNothing) {
    ImagePlacement v;
    const ImageRect r = v.rect(kArea, 300, 100);
    EXPECT_FALSE(v.imagePoint(r.x - 1, r.y + 5, kArea, 300, 100));
    EXPECT_FALSE(v.imagePoint(r.x + 5, r.y + r.height, kArea, 300, 100));
    const ImagePoint corner = *v.imagePoint(r.x, r.y, kArea, 300, 100);
    EXPECT_EQ(corner.x, 0);
    EXPECT_EQ(corner.y, 0);
    const ImagePoint beyond = v.toImage(r.x - 10, r.y + r.height + 4, kArea, 300, 100);  // a move's cursor
    EXPECT_FLOAT_EQ(beyond.x, -10 * 300 / r.width);
    EXPECT_FLOAT_EQ(beyond.y, 100 + 4 * 100 / r.height);
    v.actualPixels();
    v.zoomBy(8.0f, 680, 220, kArea, 300, 100);  // the image overflows the area: the panel's pixels map to nothing
    EXPECT_FALSE(v.imagePoint(kArea.x - 2, 220, kArea, 300, 100));
}

}  // namespace
}  // namespace trazo
