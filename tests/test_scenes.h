// Scenes and diagnostics as the tests use them: a repository scene read without errors, a scene text several
// suites render, and diagnostics as text to compare or print.
#pragma once

#include <string>

#include "scene/diagnostic.h"
#include "scene/scene.h"

namespace trazo::test {

// The scene at TRAZO_SOURCE_DIR/relative; a (non-fatal) failure of the current test when it has errors.
Scene readSourceScene(const std::string& relative);

// A sphere over a floor under a 4×4 area light (cycle 16): a penumbra, so the image is noisy. `settings`: the
// SceneSettings block's lines.
std::string penumbraSceneText(const std::string& settings);

// Each diagnostic formatted, one a line; with errorsOnly, the errors only.
std::string listedDiagnostics(const Diagnostics& diags, bool errorsOnly = false);

}  // namespace trazo::test
