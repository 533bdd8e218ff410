// Opening a scene while the viewer runs (a file dropped onto the window or a path typed in the Open panel):
// read as `trazo SCENE` reads it at start (the reader, then the render bounds), either a scene to replace the
// current one or the reasons it cannot be, as file:line messages for the UI. Host only, no UI.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace trazo {

struct OpenedScene {
    std::optional<Scene> scene;         // none when the file has errors
    std::vector<std::string> messages;  // every diagnostic, formatted (file:line: error: ...), warnings too
};

OpenedScene openSceneFile(const std::string& path);

}  // namespace trazo
