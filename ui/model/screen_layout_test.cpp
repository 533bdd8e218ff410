// Tests of the window's layout: the opening size (image at 1:1 beside the panel, clamped to the screen and to
// the minimum) and the image's area beside the panel, in framebuffer pixels on plain and HiDPI screens.
#include "model/screen_layout.h"

#include <gtest/gtest.h>

namespace trazo {
namespace {

TEST(ScreenLayout, OpensAtImagePlusPanel) {
    int w, h;
    initialWindowSize(512, 512, 380, 19, 1.0f, 1920, 1080, w, h);
    EXPECT_EQ(w, 512 + 380);
    EXPECT_EQ(h, 512 + 19);
}

TEST(ScreenLayout, ClampedToTheScreenAndTheMinimum) {
    int w, h;
    initialWindowSize(4000, 3000, 380, 19, 1.0f, 1920, 1080, w, h);
    EXPECT_EQ(w, 1728);  // 90 % of the screen
    EXPECT_EQ(h, 972);
    initialWindowSize(64, 48, 380, 19, 1.0f, 1920, 1080, w, h);
    EXPECT_EQ(w, kMinWindowWidth);
    EXPECT_EQ(h, kMinWindowHeight);
    initialWindowSize(64, 48, 380, 19, 1.0f, 500, 400, w, h);  // a screen below the minimum: the screen
    EXPECT_EQ(w, 500);
    EXPECT_EQ(h, 400);
}

TEST(ScreenLayout, HiDpiFramebufferHalvesTheImagesScreenSize) {
    int w, h;
    initialWindowSize(1024, 1024, 380, 19, 2.0f, 3000, 2000, w, h);  // 1024 pixels are 512 screen coordinates
    EXPECT_EQ(w, 512 + 380);
    EXPECT_EQ(h, 512 + 19);
}

TEST(ScreenLayout, ImageAreaIsRightOfThePanelBelowTheMenu) {
    const ImageRect a = imageArea(900, 600, 900, 600, 380, 19);
    EXPECT_EQ(a.x, 380);
    EXPECT_EQ(a.y, 19);
    EXPECT_EQ(a.width, 520);
    EXPECT_EQ(a.height, 581);
    const ImageRect hi = imageArea(900, 600, 1800, 1200, 380, 19);  // framebuffer twice the window
    EXPECT_EQ(hi.x, 760);
    EXPECT_EQ(hi.y, 38);
    EXPECT_EQ(hi.width, 1040);
    EXPECT_EQ(hi.height, 1162);
    const ImageRect none = imageArea(300, 200, 300, 200, 400, 19);  // a panel wider than the window
    EXPECT_EQ(none.width, 0);
    EXPECT_EQ(imageArea(0, 0, 0, 0, 380, 19).width, 0);
}

}  // namespace
}  // namespace trazo
