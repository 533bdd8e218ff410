// Scene reader (host): a scene file and everything it names (.csg, .obj, textures) → Scene (SPEC §1–§4).
#pragma once

#include <string>

#include "scene/diagnostic.h"
#include "scene/scene.h"

namespace trazo {

// Reads a scene file and everything it names (.csg, .obj, textures). Never exits, never throws for bad input:
// every problem goes to `diags` (errors and warnings, with file:line). The result is meaningful only when
// !diags.hasErrors().
Scene readSceneFile(const std::string& path, Diagnostics& diags);

// Same, from text; relative paths resolve against the folder of `pathForMessages`.
Scene readSceneText(const std::string& text, const std::string& pathForMessages, Diagnostics& diags);

}  // namespace trazo
