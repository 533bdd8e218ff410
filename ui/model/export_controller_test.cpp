// Tests of the viewer's export policy without a window: timestamped names that never overwrite, a default name
// used once, a typed name kept, the edited scene beside the original, the status lines, and a screenshot that
// stores what the viewer shows (SPEC §7 Image).
#include "model/export_controller.h"

#include <FreeImage.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
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

// Top-down bytes of a 24-bit file, R, G, B.
std::vector<std::array<int, 3>> readBytes(const std::string& path) {
    std::vector<std::array<int, 3>> pixels;
    FIBITMAP* bitmap = FreeImage_Load(FreeImage_GetFileType(path.c_str()), path.c_str());
    EXPECT_NE(bitmap, nullptr) << path;
    if (!bitmap) return pixels;
    const int w = int(FreeImage_GetWidth(bitmap)), h = int(FreeImage_GetHeight(bitmap));
    for (int y = h - 1; y >= 0; --y) {
        const BYTE* line = FreeImage_GetScanLine(bitmap, y);
        for (int x = 0; x < w; ++x)
            pixels.push_back({line[3 * x + FI_RGBA_RED], line[3 * x + FI_RGBA_GREEN], line[3 * x + FI_RGBA_BLUE]});
    }
    FreeImage_Unload(bitmap);
    return pixels;
}

std::vector<std::array<int, 3>> expectedBytes(const std::vector<Vec3>& image, float (*tone)(float)) {
    std::vector<std::array<int, 3>> bytes;
    const auto byte = [&](float x) { return int(std::floor(255.0 * double(tone(x)) + 0.5)); };
    for (const Vec3& p : image) bytes.push_back({byte(p.x), byte(p.y), byte(p.z)});
    return bytes;
}

TEST(ExportController, AScreenshotStoresWhatTheViewerShows) {
    const fs::path dir = freshDir("export_tone");
    const std::unique_ptr<ViewerSession> session = smallSession();
    session->renderPasses(1);
    session->scene().settings.exposure = 1.5f;  // the image transform only: nothing to re-render
    session->scene().settings.viewTransform = ViewTransform::Srgb;
    const std::vector<Vec3> image = session->image();
    ASSERT_TRUE(std::any_of(image.begin(), image.end(), [](const Vec3& p) { return p.x > 0.0f && p.x < 0.5f; }))
        << "a lit pixel that the exposure and the tone change";
    std::string message;
    // 2^1.5, then sRGB, as the display shows it.
    ASSERT_TRUE(saveSessionImage(*session, (dir / "shot.png").string(), message)) << message;
    EXPECT_EQ(readBytes((dir / "shot.png").string()), expectedBytes(image, [](float x) {
                  return DisplayTransform{std::exp2(1.5f), true}.encode(x);
              }));
    // A float file stores the exposed value, linear.
    ASSERT_TRUE(saveSessionImage(*session, (dir / "shot.exr").string(), message));
    FIBITMAP* exr = FreeImage_Load(FIF_EXR, (dir / "shot.exr").c_str());
    ASSERT_NE(exr, nullptr);
    const int w = int(FreeImage_GetWidth(exr)), h = int(FreeImage_GetHeight(exr));
    ASSERT_EQ(size_t(w) * size_t(h), image.size());
    for (int y = 0; y < h; ++y) {
        const auto* line = reinterpret_cast<const FIRGBF*>(FreeImage_GetScanLine(exr, h - 1 - y));
        for (int x = 0; x < w; ++x) EXPECT_EQ(line[x].red, std::exp2(1.5f) * image[size_t(y) * w + x].x);
    }
    FreeImage_Unload(exr);
}

}  // namespace
}  // namespace trazo
