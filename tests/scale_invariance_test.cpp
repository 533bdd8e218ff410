// SPEC §5's "at any scene scale", in whole renders: secondary rays leave a hit by an offset from the hit point's
// own rounding error, so an image does not change when the camera backs away, when the whole scene moves far from
// the origin or when it is scaled, up to the pixels float32 itself cannot decide. The checks that caught the
// offset that grew with the camera's distance: the subsurface slab's reflectance, a thin pane's Fresnel
// transmission, and the seed scenes moved and scaled.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render_harness.h"
#include "scene/scene.h"
#include "support/halfspace_walk.h"
#include "test_paths.h"

namespace trazo::test {
namespace {

std::string vec(Vec3 v) {
    return std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z);
}

struct ChannelMean {
    double mean, standardError;
};

ChannelMean meanOf(const RenderedImage& image, int channel) {
    double sum = 0, sum2 = 0;
    for (const Vec3& p : image.pixels) sum += p[channel], sum2 += double(p[channel]) * p[channel];
    const double count = double(image.pixels.size()), mean = sum / count;
    return {mean, std::sqrt(std::max(0.0, sum2 / count - mean * mean) / count)};
}

// SPEC §6's thick slab (Kd 0.8, no surface lobe; 400 mean free paths thick) lit and seen head-on from `distance`
// away, the whole scene moved by `shift`: R(0.8) = 0.342 whatever the distance, the place and the mean free path.
// Each of the 32×32 pixels × 32 passes is an independent walk; the bound is 4.5 standard errors of their mean
// (about 2.5 % of R), where the offset that grew with the camera's distance read 0.298 at 100 and 0.104 at 1 000.
TEST(ScaleInvarianceRender, SubsurfaceSlabKeepsItsReflectanceAtEveryDistanceAndPlace) {
    const double reference = halfspaceReflectanceChandrasekhar(0.8);
    struct Case {
        float distance;
        Vec3 shift;
        float meanFreePath;
    };
    for (const Case c : {Case{10, Vec3(0), 0.01f}, Case{100, Vec3(0), 0.01f}, Case{1000, Vec3(0), 0.01f},
                         Case{10, Vec3(0), 0.0005f}, Case{10, Vec3(1000, -700, 400), 0.1f}}) {
        const std::string scene =
            "SceneSettings\n{\nRenderWidth 32\nRenderHeight 32\nReflectionQuality 0\nIndirectQuality 0\n}\n"
            "Camera\n{\nPOV " + vec(c.shift + Vec3(0, 0, c.distance)) + "\nPOI " + vec(c.shift) + "\nFOV " +
            std::to_string(20.0f / c.distance) + "\n}\n"
            "PointLight\n{\nPosition " + vec(c.shift + Vec3(0, 0, 100000)) + "\n}\n"
            "Material\n{\nName wax\nDiffuseColor 0.8 0.8 0.8\nSpecularColor 0 0 0\nScatteringDistance " +
            std::to_string(c.meanFreePath) + " " + std::to_string(c.meanFreePath) + " " +
            std::to_string(c.meanFreePath) + "\n}\n"
            "Box\n{\nMaterial wax\nScale " + vec(Vec3(4000, 4000, 400) * c.meanFreePath) + "\nTranslation " +
            vec(c.shift + Vec3(0, 0, -200 * c.meanFreePath)) + "\n}\n";
        const RenderedImage image = renderSceneText(scene, {.passes = 32});
        ASSERT_FALSE(image.pixels.empty());
        const ChannelMean r = meanOf(image, 1);
        EXPECT_NEAR(r.mean, reference, 4.5 * r.standardError)
            << "camera " << c.distance << " away, scene moved by " << vec(c.shift) << ", mean free path "
            << c.meanFreePath << " (standard error " << r.standardError << ")";
    }
}

// SPEC §6's Fresnel check through a pane 0.01 thick seen head-on from 1 000 away: (1 − F)/(1 + F) = 0.96/1.04
// of the emitter behind it comes through, as at any distance; stepping over the pane's back face reads 0.96.
TEST(ScaleInvarianceRender, ThinPaneFromFarAwayTransmitsOneMinusFOverOnePlusF) {
    const std::string scene =
        "SceneSettings\n{\nRenderWidth 32\nRenderHeight 32\nReflectionQuality 1\nIndirectQuality 0\n}\n"
        "Camera\n{\nPOV 0 0 1000\nPOI 0 0 0\nFOV 0.05\n}\n"
        "Material\n{\nName glass\nDiffuseColor 0 0 0\nSpecularColor 0 0 0\nOpacity 0\nRefractionIndex 1.5\n"
        "Fresnel 1\n}\n"
        "Material\n{\nName wall\nDiffuseColor 0 0 0\nSpecularColor 0 0 0\nEmissiveColor 1 1 1\n}\n"
        "Box\n{\nMaterial glass\nScale 100 100 0.01\n}\n"
        "Box\n{\nMaterial wall\nTranslation 0 0 -5\nScale 1000 1000 1\n}\n";
    const RenderedImage image = renderSceneText(scene, {.passes = 64});
    ASSERT_FALSE(image.pixels.empty());
    EXPECT_NEAR(meanOf(image, 1).mean, 0.96 / 1.04, 4 * 7.3e-4);
}

// Pixels of two renders of one scene that differ by more than `tolerance` in some channel.
double differingShare(const RenderedImage& a, const RenderedImage& b, float tolerance) {
    size_t differing = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        if (maxComponent(abs(a.pixels[i] - b.pixels[i])) > tolerance) ++differing;
    return double(differing) / double(a.pixels.size());
}

// Seed scenes of every object kind, with refraction, mirrors and glossy cones, moved by 10³ and 10⁴ (camera and
// lights too) and scaled by 10⁻³ and 10⁴: the same image but for pixels that float32 cannot decide (silhouettes
// and edges, where a hit point's rounding at 10⁴ is a visible fraction of a pixel's footprint).
TEST(ScaleInvarianceRender, SeedScenesMovedAndScaledKeepTheirImage) {
    struct Change {
        const char* name;
        std::function<void(Scene&)> apply;
        double allowedShare;
    };
    const Change changes[] = {
        {"moved by 1e3", [](Scene& s) { translateScene(s, Vec3(1000, -700, 400)); }, 0.01},
        {"moved by 1e4", [](Scene& s) { translateScene(s, Vec3(10000, -7000, 4000)); }, 0.05},
        {"scaled by 1e-3", [](Scene& s) { scaleSceneAboutOrigin(s, 1e-3); }, 0.01},
        {"scaled by 1e4", [](Scene& s) { scaleSceneAboutOrigin(s, 1e4); }, 0.01},
    };
    for (const char* name : {"scene7_refract", "scene3_csg", "scene4_reflect", "effect_fresnel"}) {
        const std::string path = sourcePath("scenes/" + std::string(name) + ".scene");
        const RenderRequest plain{.width = 96, .height = 72};
        const RenderedImage reference = renderSceneFile(path, plain);
        ASSERT_FALSE(reference.pixels.empty()) << name;
        for (const Change& change : changes) {
            RenderRequest request = plain;
            request.editScene = change.apply;
            const RenderedImage image = renderSceneFile(path, request);
            ASSERT_EQ(image.pixels.size(), reference.pixels.size());
            EXPECT_LE(differingShare(reference, image, 0.05f), change.allowedShare) << name << " " << change.name;
        }
    }
}

}  // namespace
}  // namespace trazo::test
