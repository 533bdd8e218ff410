// ExportController: timestamped names, the image and scene writers, and the status lines they leave.
#include "model/export_controller.h"

#include <cstdio>
#include <filesystem>

#include "image/image_writer.h"
#include "model/setting_effects.h"
#include "scene/scene_writer.h"

namespace trazo {
namespace {

void copyString(char* dst, size_t size, const std::string& src) { std::snprintf(dst, size, "%s", src.c_str()); }

void report(const std::string& status) { std::fprintf(stderr, "trazo: %s\n", status.c_str()); }

}  // namespace

std::string timestampedName(const std::string& extension, std::time_t when, const std::string& folder) {
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&when));
    const std::filesystem::path dir(folder);
    std::string name = std::string("trazo-") + stamp + extension;
    for (int i = 2; std::filesystem::exists(dir / name); ++i)
        name = std::string("trazo-") + stamp + "-" + std::to_string(i) + extension;
    return name;
}

std::string editedScenePath(const std::string& scenePath) {
    const std::filesystem::path p(scenePath);
    return (p.parent_path() / (p.stem().string() + "-edited.scene")).string();
}

bool saveSessionImage(ViewerSession& session, const std::string& path, std::string& message) {
    std::string error;
    if (!writeImage(path, int(session.width()), int(session.height()), session.image(), error,
                    displayTransformOf(session.scene()))) {
        message = error;
        return false;
    }
    message = "saved " + path + " (" + std::to_string(session.accumulation().passes()) + " passes)";
    return true;
}

ExportController::ExportController(const std::string& scenePath, const std::string& screenshot, PanelState& state) {
    if (screenshot.empty()) showDefault(".png", state);
    else copyString(state.screenshotPath, sizeof state.screenshotPath, screenshot);
    copyString(state.scenePath, sizeof state.scenePath, editedScenePath(scenePath));
}

void ExportController::showDefault(const std::string& extension, PanelState& state) {
    defaultName_ = timestampedName(extension.empty() ? ".png" : extension, std::time(nullptr));
    copyString(state.screenshotPath, sizeof state.screenshotPath, defaultName_);
}

void ExportController::renameScreenshot(PanelState& state) {
    showDefault(std::filesystem::path(state.screenshotPath).extension().string(), state);
}

void ExportController::saveScreenshot(ViewerSession& session, PanelState& state) {
    const std::string path = state.screenshotPath;
    saveSessionImage(session, path, state.status);
    report(state.status);
    if (!defaultName_.empty() && path == defaultName_)
        showDefault(std::filesystem::path(path).extension().string(), state);
}

bool ExportController::saveScene(const Scene& scene, PanelState& state) {
    std::string error;
    const std::string path = state.scenePath;
    const bool saved = writeSceneFile(scene, path, error);
    state.status = saved ? "saved scene " + path : error;
    report(state.status);
    return saved;
}

}  // namespace trazo
