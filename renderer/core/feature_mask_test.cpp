// Tests of the feature list: one bit and one distinct word per feature, and describeFeatures naming them all.
#include "core/feature_mask.h"

#include <gtest/gtest.h>

#include <bitset>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace trazo {
namespace {

FeatureMask allFeatures() {
    FeatureMask all = 0;
    for (const FeatureName& f : kFeatureNames) all |= f.bit;
    return all;
}

TEST(FeatureMask, EachFeatureHasItsOwnBitAndWord) {
    std::set<std::string> names;
    for (uint32_t i = 0; i < kFeatureCount; ++i) {
        const FeatureName& f = kFeatureNames[i];
        EXPECT_EQ((uint32_t)f.bit, 1u << i) << f.name;
        ASSERT_NE(f.name, nullptr);
        const std::string name = f.name;
        EXPECT_FALSE(name.empty()) << "bit " << i;
        EXPECT_EQ(name.find(' '), std::string::npos) << name << ": describeFeatures separates words by spaces";
        EXPECT_TRUE(names.insert(name).second) << name << " names two bits";
    }
    EXPECT_EQ(std::bitset<32>(allFeatures()).count(), (size_t)kFeatureCount);
}

TEST(FeatureMask, DescribeNamesEveryFeatureOnceInListOrder) {
    std::istringstream words(describeFeatures(allFeatures()));
    std::vector<std::string> got;
    for (std::string w; words >> w;) got.push_back(w);
    std::vector<std::string> expected;
    for (const FeatureName& f : kFeatureNames) expected.push_back(f.name);
    EXPECT_EQ(got, expected);
}

TEST(FeatureMask, DescribeNamesOnlyTheBitsSet) {
    EXPECT_EQ(describeFeatures(0), "none");
    EXPECT_EQ(describeFeatures(kFeatureAreaLights | kFeatureCsg), "area-lights csg");
    EXPECT_EQ(describeFeatures(kFeaturePointLights), "point-lights");
    EXPECT_EQ(describeFeatures(kFeatureIndirect | kFeatureGlossy), "glossy indirect");
}

}  // namespace
}  // namespace trazo
