// The viewer's edit of SceneSettings' EnvironmentMap (host, no UI): the path as the scene file writes it, and a
// new path read into the scene, or the old map kept with the reason when the image does not read.
#pragma once

#include <string>

#include "scene/scene.h"

namespace trazo {

// The map's path as the scene writer writes it (relative to the scene's folder); "" when there is none.
std::string environmentMapText(const Scene& scene);

// Makes `written` (relative paths from the scene's folder, as the reader resolves them; surrounding blanks
// ignored) the scene's EnvironmentMap and reads its image; "" removes the map. True when the scene changed.
// When the image does not read, the scene keeps its old map and `message` says why; a success clears it.
bool setEnvironmentMap(Scene& scene, const std::string& written, std::string& message);

}  // namespace trazo
