// The specialised instances of renderSample<F> give exactly the image of the all-features oracle.
#include <gtest/gtest.h>

#include <filesystem>

#include "flatten/flatten.h"
#include "fetched_assets.h"
#include "integrator/sample_variants.h"
#include "render_harness.h"
#include "scene/scene_reader.h"
#include "test_paths.h"

namespace trazo::test {
namespace {

TEST(FeatureVariants, EveryShippedSceneMatchesTheAllFeaturesOracleBitForBit) {
    int scenes = 0;
    std::string absent;  // the scenes not compared, and why
    for (const auto& entry : std::filesystem::directory_iterator(sourcePath("scenes"))) {
        if (entry.path().extension() != ".scene") continue;
        ++scenes;
        if (const std::string why = absentFetchedAsset(entry.path().string()); !why.empty()) {
            absent += "\n" + why;
            continue;
        }
        const RenderRequest request{.passes = 3, .seed = 7, .width = 40, .height = 40};
        RenderRequest oracle = request;
        oracle.allFeatures = true;
        const RenderedImage specialised = renderSceneFile(entry.path().string(), request);
        const RenderedImage reference = renderSceneFile(entry.path().string(), oracle);
        ASSERT_EQ(specialised.pixels.size(), reference.pixels.size()) << entry.path();
        for (size_t i = 0; i < specialised.pixels.size(); ++i) {
            ASSERT_EQ(specialised.pixels[i].x, reference.pixels[i].x) << entry.path() << " pixel " << i;
            ASSERT_EQ(specialised.pixels[i].y, reference.pixels[i].y) << entry.path() << " pixel " << i;
            ASSERT_EQ(specialised.pixels[i].z, reference.pixels[i].z) << entry.path() << " pixel " << i;
        }
        EXPECT_EQ(specialised.rays, reference.rays) << entry.path();
    }
    EXPECT_GE(scenes, 19);
    if (!absent.empty()) GTEST_SKIP() << "not compared:" << absent;
}

TEST(FeatureVariants, SceneFeaturesPickTheMatchingInstance) {
    auto variantOf = [](const char* name) {
        Diagnostics diags;
        const Scene scene = readSceneFile(sourcePath(std::string("scenes/") + name), diags);
        const FlattenResult flat = flatten(scene);
        return sampleVariantFor(flat.arrays.settings.integrator, flat.arrays.features);
    };
    EXPECT_EQ(sampleVariant(variantOf("scene1_point.scene")).features, 0u);
    EXPECT_EQ(sampleVariant(variantOf("scene1_area.scene")).features, kFeatureAreaLights);
    EXPECT_EQ(sampleVariant(variantOf("scene4_reflect.scene")).features, kFeatureAreaLights | kFeatureReflection);
    EXPECT_EQ(sampleVariant(variantOf("scene7_refract.scene")).features, kFeatureAreaLights | kFeatureRefraction);
    // SPEC §6's dispersion and subsurface scattering share the one instance with every feature on.
    EXPECT_EQ(variantOf("effect_dispersion.scene"), kAllFeaturesVariant);
    EXPECT_EQ(variantOf("effect_subsurface.scene"), kAllFeaturesVariant);
    EXPECT_EQ(variantOf("effect_fresnel.scene"), variantOf("scene7_refract.scene") | 2u) << "Fresnel glass reflects";
}

}  // namespace
}  // namespace trazo::test
