// Pass ranges: what --passes accepts, and the merge's union and missing ranges.
#include "render/pass_range.h"

#include <gtest/gtest.h>

namespace trazo {
namespace {

TEST(PassRange, ParsesFirstColonEnd) {
    PassRange r;
    std::string why;
    ASSERT_TRUE(parsePassRange("16:24", r, why, 100));
    EXPECT_EQ(r, (PassRange{16, 24}));
    EXPECT_EQ(r.count(), 8u);
    EXPECT_EQ(formatRange(r), "16:24");
    for (const char* bad : {"", "16", "16:", ":24", "24:16", "8:8", "-1:4", "1:2:3", "a:b", "0:101", " 1:2"})
        EXPECT_FALSE(parsePassRange(bad, r, why, 100)) << bad;
    EXPECT_FALSE(parsePassRange("8:8", r, why, 100));
    EXPECT_NE(why.find("greater"), std::string::npos) << why;
}

TEST(PassRange, JoinsAndFindsWhatIsMissing) {
    const std::vector<PassRange> parts{{24, 32}, {0, 8}, {8, 16}, {40, 41}};
    EXPECT_EQ(joinRanges(parts), (std::vector<PassRange>{{0, 16}, {24, 32}, {40, 41}}));
    EXPECT_EQ(passCount(joinRanges(parts)), 25u);
    EXPECT_EQ(formatRanges(missingRanges({0, 48}, parts)), "16:24,32:40,41:48");
    EXPECT_EQ(formatRanges(missingRanges({4, 12}, parts)), "");
    EXPECT_EQ(formatRanges(missingRanges({0, 8}, {})), "0:8");
    EXPECT_EQ(intersect({0, 10}, {8, 16}), (PassRange{8, 10}));
    EXPECT_EQ(intersect({0, 8}, {8, 16}).count(), 0u);
}

}  // namespace
}  // namespace trazo
