// Tests of the outline: a filled rectangle keeps its border ring, the image's edge counts as outside, an empty
// or mismatched mask gives none.
#include "model/selection_outline.h"

#include <gtest/gtest.h>

namespace trazo {
namespace {

TEST(SelectionOutline, ARectangleKeepsItsBorderRing) {
    const uint32_t w = 6, h = 5;
    std::vector<uint8_t> mask(w * h, 0);
    for (uint32_t y = 1; y <= 3; ++y)
        for (uint32_t x = 1; x <= 4; ++x) mask[y * w + x] = 1;  // a 4 × 3 block
    const std::vector<uint8_t> edge = outlineOf(mask, w, h);
    const char* expected =
        "......"
        ".####."
        ".#..#."
        ".####."
        "......";
    for (uint32_t i = 0; i < w * h; ++i) EXPECT_EQ(edge[i], expected[i] == '#') << "pixel " << i;
}

TEST(SelectionOutline, TheImageEdgeIsOutside) {
    const std::vector<uint8_t> mask(3 * 3, 1);
    const std::vector<uint8_t> edge = outlineOf(mask, 3, 3);
    for (uint32_t i = 0; i < 9; ++i) EXPECT_EQ(edge[i], i == 4 ? 0 : 1) << "pixel " << i;
}

TEST(SelectionOutline, NothingSelectedOrAMismatchGivesNone) {
    EXPECT_EQ(outlineOf(std::vector<uint8_t>(12, 0), 4, 3), std::vector<uint8_t>(12, 0));
    EXPECT_EQ(outlineOf(std::vector<uint8_t>(5, 1), 4, 3), std::vector<uint8_t>(5, 0));
}

}  // namespace
}  // namespace trazo
