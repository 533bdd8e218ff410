// EnvironmentMap edits: resolved as the reader resolves them, read through the reader's image reader.
#include "model/environment_edit.h"

#include "io/text_file.h"
#include "scene/block_table.h"
#include "scene/environment_reader.h"

namespace trazo {
namespace {

std::string trimmed(const std::string& s) {
    const size_t first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

}  // namespace

std::string environmentMapText(const Scene& scene) {
    if (scene.settings.environmentMap.empty()) return {};
    for (const ParamSpec<SceneSettings>& row : sceneSettingsTable()) {
        if (row.info.name != "EnvironmentMap") continue;
        std::vector<ParamValue> values;
        row.extract(scene.settings, values);
        if (values.size() != 1) break;
        const std::string quoted = formatValues(row.info, values[0], scene.path);
        return quoted.size() >= 2 ? quoted.substr(1, quoted.size() - 2) : quoted;
    }
    return scene.settings.environmentMap;
}

bool setEnvironmentMap(Scene& scene, const std::string& written, std::string& message) {
    SceneSettings& s = scene.settings;
    const std::string text = trimmed(written);
    const std::string path = text.empty() ? std::string() : resolveRelativePath(scene.path, text);
    if (path == s.environmentMap) {
        message.clear();
        return false;
    }
    std::shared_ptr<const TextureImage> image;
    if (!path.empty()) {
        Diagnostics diags;
        image = readEnvironmentMap(path, SourceLocation{}, diags);  // as the reader does (scene_reader.cpp)
        if (!image || diags.hasErrors()) {
            message.clear();
            for (const Diagnostic& d : diags.items) {
                if (d.severity != Severity::Error) continue;
                if (!message.empty()) message += '\n';
                message += "EnvironmentMap: " + d.message;
            }
            if (message.empty()) message = "EnvironmentMap: cannot read '" + path + "'";
            message += s.environmentMap.empty() ? "; still none" : "; the old map stays";
            return false;
        }
    }
    s.environmentMap = path;
    s.environmentImage = std::move(image);
    s.environmentMapAt = {};
    message.clear();
    return true;
}

}  // namespace trazo
