// Tests of the viewer's export policy without a window: timestamped names that never overwrite, a default name
// used once, a typed name kept, the edited scene beside the original, and the status lines.
#include "model/export_controller.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "backends/backend.h"
#include "scene/scene_reader.h"
#include "test_paths.h"

namespace trazo {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) { return test::freshDir(name); }

// The current folder for one test (the viewer names its defaults relative to it).
class InFolder {
public:
    explicit InFolder(const fs::path& dir) : previous_(fs::current_path()) { fs::current_path(dir); }
    ~InFolder() { fs::current_path(previous_); }

private:
    fs::path previous_;
};

std::unique_ptr<ViewerSession> smallSession() {
    Diagnostics diags;
    Scene scene = readSceneFile(test::sourcePath("scenes/scene1_area.scene"), diags);
    EXPECT_FALSE(diags.hasErrors());
    return std::make_unique<ViewerSession>(std::move(scene), createCpuBackend(1), 0, 8, 6);
}

TEST(ExportController, TimestampedNamesNeverNameAnExistingFile) {
    const fs::path dir = freshDir("export_names");
    std::tm noon{};
    noon.tm_year = 2024 - 1900;
    noon.tm_mon = 2;
    noon.tm_mday = 5;
    noon.tm_hour = 12;
    noon.tm_min = 34;
    noon.tm_sec = 56;
    noon.tm_isdst = -1;
    const std::time_t when = std::mktime(&noon);
    EXPECT_EQ(timestampedName(".png", when, dir.string()), "trazo-20240305-123456.png");
    std::ofstream(dir / "trazo-20240305-123456.png") << "x";
    EXPECT_EQ(timestampedName(".png", when, dir.string()), "trazo-20240305-123456-2.png");
    std::ofstream(dir / "trazo-20240305-123456-2.png") << "x";
    EXPECT_EQ(timestampedName(".png", when, dir.string()), "trazo-20240305-123456-3.png");
    EXPECT_EQ(timestampedName(".exr", when, dir.string()), "trazo-20240305-123456.exr");
}

TEST(ExportController, EditedSceneGoesBesideTheOriginal) {
    EXPECT_EQ(editedScenePath("scenes/scene1_area.scene"), "scenes/scene1_area-edited.scene");
    EXPECT_EQ(editedScenePath("a.scene"), "a-edited.scene");
    PanelState state;
    ExportController exports("dir/b.scene", "shot.exr", state);
    EXPECT_STREQ(state.scenePath, "dir/b-edited.scene");
    EXPECT_STREQ(state.screenshotPath, "shot.exr");
}

TEST(ExportController, ADefaultNameIsUsedOnceATypedNameStays) {
    const fs::path dir = freshDir("export_default");
    const InFolder here(dir);
    const std::unique_ptr<ViewerSession> session = smallSession();
    PanelState state;
    ExportController exports("a.scene", "", state);
    const std::string first = state.screenshotPath;
    EXPECT_EQ(first.rfind("trazo-", 0), 0u) << first;
    EXPECT_EQ(fs::path(first).extension(), ".png");

    testing::internal::CaptureStderr();
    exports.saveScreenshot(*session, state);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "trazo: saved " + first + " (0 passes)\n");
    EXPECT_EQ(state.status, "saved " + first + " (0 passes)");
    EXPECT_TRUE(fs::exists(dir / first));
    const std::string second = state.screenshotPath;
    EXPECT_NE(second, first);  // the next screenshot gets a fresh name
    EXPECT_FALSE(fs::exists(dir / second));

    std::snprintf(state.screenshotPath, sizeof state.screenshotPath, "%s", "typed.bmp");
    testing::internal::CaptureStderr();
    exports.saveScreenshot(*session, state);
    testing::internal::GetCapturedStderr();
    EXPECT_STREQ(state.screenshotPath, "typed.bmp");
    EXPECT_TRUE(fs::exists(dir / "typed.bmp"));

    exports.renameScreenshot(state);  // "New name" keeps the field's extension
    EXPECT_EQ(fs::path(state.screenshotPath).extension(), ".bmp");
    EXPECT_EQ(std::string(state.screenshotPath).rfind("trazo-", 0), 0u);
}

TEST(ExportController, FailedSavesSayWhy) {
    const std::unique_ptr<ViewerSession> session = smallSession();
    PanelState state;
    const std::string missing = (freshDir("export_fail") / "no_such_folder").string();
    ExportController exports(missing + "/a.scene", missing + "/shot.png", state);
    testing::internal::CaptureStderr();
    exports.saveScreenshot(*session, state);
    exports.saveScene(session->scene(), state);
    const std::string printed = testing::internal::GetCapturedStderr();
    EXPECT_NE(printed.find("trazo: cannot write '" + missing + "/shot.png': folder"), std::string::npos) << printed;
    EXPECT_EQ(state.status.rfind("cannot write '" + missing + "/a-edited.scene'", 0), 0u) << state.status;
    EXPECT_STREQ(state.screenshotPath, (missing + "/shot.png").c_str());
}

TEST(ExportController, SavesTheSceneItIsGiven) {
    const fs::path dir = freshDir("export_scene");
    const std::unique_ptr<ViewerSession> session = smallSession();
    PanelState state;
    ExportController exports((dir / "a.scene").string(), "x.png", state);
    testing::internal::CaptureStderr();
    exports.saveScene(session->scene(), state);
    testing::internal::GetCapturedStderr();
    EXPECT_EQ(state.status, "saved scene " + (dir / "a-edited.scene").string());
    Diagnostics diags;
    const Scene back = readSceneFile((dir / "a-edited.scene").string(), diags);
    EXPECT_FALSE(diags.hasErrors());
    EXPECT_EQ(back.materials.size(), session->scene().materials.size());
}

}  // namespace
}  // namespace trazo
