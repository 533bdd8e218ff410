// Scene writer (host): a Scene back to the scene language (SPEC §3), so an edited scene can be saved and read
// again. The viewer's "save scene" uses it.
#pragma once

#include <string>

#include "scene/scene.h"

namespace trazo {

// The scene as scene-language text that readSceneText (with `scenePath` as its path) turns back into the same
// scene: every block and field, floats with enough digits to read back bit for bit, transforms in their
// written order. Paths of textures, meshes and CSG files are written relative to the folder of `scenePath`
// (absolute when they are on another root). Objects on the default material get no Material line.
std::string formatScene(const Scene& scene, const std::string& scenePath);

// Writes formatScene(scene, path) to `path` through a temporary file renamed over it, so a failure leaves any
// existing file as it was. False with a plain reason in `error` on failure.
bool writeSceneFile(const Scene& scene, const std::string& path, std::string& error);

}  // namespace trazo
