// The recovery file: formatScene's text, written through writeTextFileAtomically at most once an interval.
#include "model/recovery_file.h"

#include <filesystem>
#include <system_error>

#include "io/text_file.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"

namespace trazo {

RecoveryFile::RecoveryFile(std::string scenePath, Clock::duration interval)
    : scenePath_(std::move(scenePath)), path_(scenePath_.empty() ? "" : pathFor(scenePath_)), interval_(interval) {}

std::string RecoveryFile::pathFor(const std::string& scenePath) { return scenePath + ".recovery"; }

std::optional<std::string> RecoveryFile::find(const std::string& scenePath) {
    if (scenePath.empty()) return std::nullopt;
    std::error_code ec;
    const std::string path = pathFor(scenePath);
    if (std::filesystem::is_regular_file(path, ec)) return path;
    return std::nullopt;
}

Scene RecoveryFile::read(const std::string& scenePath, Diagnostics& diags) {
    Scene scene = readSceneFile(pathFor(scenePath), diags);
    scene.path = scenePath;
    return scene;
}

bool RecoveryFile::write(const Scene& scene, bool unsaved, bool force, Clock::time_point now) {
    if (path_.empty()) return false;
    if (!unsaved) {
        if (!exists_) return false;
        remove();
        return true;
    }
    if (!force && lastWrite_ && now - *lastWrite_ < interval_) return false;
    lastWrite_ = now;
    std::string text = formatScene(scene, scenePath_);
    if (exists_ && text == written_) return false;
    if (!writeTextFileAtomically(path_, text, error_)) return false;
    error_.clear();
    written_ = std::move(text);
    exists_ = true;
    return true;
}

void RecoveryFile::remove() {
    if (path_.empty()) return;
    std::error_code ec;
    std::filesystem::remove(path_, ec);
    exists_ = false;
    written_.clear();
}

}  // namespace trazo
