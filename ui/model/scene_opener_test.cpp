// Tests of the run-time open: a good scene comes back with its path, a malformed one or one past the render
// bounds comes back as file:line messages and no scene, a missing file names the file.
#include "model/scene_opener.h"

#include <gtest/gtest.h>

#include "test_paths.h"

namespace trazo {
namespace {

TEST(SceneOpener, AGoodSceneOpens) {
    const std::string path = test::writeTempFile("good.scene", "Sphere {\n  Center 0 0 0\n  Radius 2\n}\n");
    const OpenedScene opened = openSceneFile(path);
    ASSERT_TRUE(opened.scene);
    for (const std::string& m : opened.messages) EXPECT_EQ(m.find("error:"), std::string::npos) << m;  // warnings
    ASSERT_EQ(opened.scene->spheres.size(), 1u);
    EXPECT_EQ(opened.scene->spheres[0].radius, 2.0f);
}

TEST(SceneOpener, ErrorsComeBackAsFileLineMessages) {
    const std::string path = test::writeTempFile("bad.scene", "Sphere {\n  Center 0 0 0\n  Radius -2\n}\n");
    const OpenedScene opened = openSceneFile(path);
    EXPECT_FALSE(opened.scene);
    ASSERT_FALSE(opened.messages.empty());
    EXPECT_EQ(opened.messages[0].rfind(path + ":3:", 0), 0u) << opened.messages[0];
    EXPECT_NE(opened.messages[0].find("error:"), std::string::npos) << opened.messages[0];
}

TEST(SceneOpener, RenderBoundsAreCheckedAsAtStart) {
    const std::string path = test::writeTempFile("bounds.scene", "SceneSettings {\n  IndirectQuality 725\n}\n");
    const OpenedScene opened = openSceneFile(path);
    EXPECT_FALSE(opened.scene);
    ASSERT_EQ(opened.messages.size(), 1u);
    EXPECT_EQ(opened.messages[0].rfind(path + ":2:", 0), 0u) << opened.messages[0];
}

TEST(SceneOpener, AMissingFileIsNamed) {
    const std::string path = test::tempPath("absent.scene");
    const OpenedScene opened = openSceneFile(path);
    EXPECT_FALSE(opened.scene);
    ASSERT_FALSE(opened.messages.empty());
    EXPECT_NE(opened.messages[0].find(path), std::string::npos) << opened.messages[0];
}

}  // namespace
}  // namespace trazo
