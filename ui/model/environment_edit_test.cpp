// Tests of the viewer's EnvironmentMap edit: a path typed relative to the scene is read into the scene and
// shown back as the file writes it; a file that does not read leaves the old map and says why; "" removes it.
#include "model/environment_edit.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "model/viewer_session.h"
#include "test_paths.h"

namespace trazo {
namespace {

// A 2 × 1 float image (PFM: a text header, then little-endian floats bottom row first).
std::string writeSky(const std::string& name) {
    const float texels[6] = {0.25f, 0.5f, 1.0f, 2.0f, 0.0f, 0.125f};
    std::string bytes = "PF\n2 1\n-1.0\n";
    bytes.append(reinterpret_cast<const char*>(texels), sizeof texels);
    return test::writeTempFile(name, bytes);
}

TEST(EnvironmentEdit, APathRelativeToTheSceneIsReadAndShownAsWritten) {
    const std::string sky = writeSky("env_sky.pfm");
    Scene scene;
    scene.path = (std::filesystem::path(sky).parent_path() / "env.scene").string();
    std::string message = "stale";
    EXPECT_TRUE(setEnvironmentMap(scene, "  env_sky.pfm ", message));
    EXPECT_TRUE(message.empty());
    EXPECT_TRUE(std::filesystem::equivalent(scene.settings.environmentMap, sky));
    ASSERT_TRUE(scene.settings.environmentImage);
    EXPECT_EQ(scene.settings.environmentImage->width, 2);
    EXPECT_FLOAT_EQ(scene.settings.environmentImage->texels[1].x, 2.0f);
    EXPECT_EQ(environmentMapText(scene), "env_sky.pfm");
    EXPECT_FALSE(setEnvironmentMap(scene, "env_sky.pfm", message));  // the same map: no edit
    EXPECT_TRUE(message.empty());
}

TEST(EnvironmentEdit, AFileThatDoesNotReadKeepsTheOldMap) {
    const std::string sky = writeSky("env_keep.pfm");
    Scene scene;
    scene.path = (std::filesystem::path(sky).parent_path() / "env.scene").string();
    std::string message;
    ASSERT_TRUE(setEnvironmentMap(scene, sky, message));  // absolute paths too
    const auto image = scene.settings.environmentImage;
    const std::string junk = test::writeTempFile("env_junk.hdr", "not an image");
    for (const std::string& bad : {std::string("missing_sky.hdr"), junk}) {
        EXPECT_FALSE(setEnvironmentMap(scene, bad, message)) << bad;
        EXPECT_NE(message.find("EnvironmentMap: "), std::string::npos) << message;
        EXPECT_NE(message.find(std::filesystem::path(bad).filename().string()), std::string::npos) << message;
        EXPECT_NE(message.find("the old map stays"), std::string::npos) << message;
        EXPECT_EQ(scene.settings.environmentMap, sky);
        EXPECT_EQ(scene.settings.environmentImage, image);
    }
    // The scene with its map still renders in the viewer.
    scene.settings.renderWidth = 8;
    scene.settings.renderHeight = 6;
    scene.spheres.push_back(Sphere{kDefaultMaterial, Vec3(0, 0, 0), 1.0f, {}});
    ViewerSession session(scene, createCpuBackend(2), 0);
    session.renderPasses(1);
    EXPECT_EQ(session.accumulation().passes(), 1u);
}

TEST(EnvironmentEdit, AnEmptyPathRemovesTheMap) {
    const std::string sky = writeSky("env_remove.pfm");
    Scene scene;
    scene.path = (std::filesystem::path(sky).parent_path() / "env.scene").string();
    std::string message;
    ASSERT_TRUE(setEnvironmentMap(scene, sky, message));
    EXPECT_TRUE(setEnvironmentMap(scene, " ", message));
    EXPECT_TRUE(scene.settings.environmentMap.empty());
    EXPECT_FALSE(scene.settings.environmentImage);
    EXPECT_EQ(environmentMapText(scene), "");
    EXPECT_FALSE(setEnvironmentMap(scene, "missing_sky.hdr", message));
    EXPECT_NE(message.find("still none"), std::string::npos) << message;
}

}  // namespace
}  // namespace trazo
