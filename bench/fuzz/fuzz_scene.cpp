// libFuzzer harness: scene text → readSceneText (and every .csg, .obj and texture it names, relative to
// fuzz::sceneRoot()) → checkRenderBounds → flatten → one pass of an 8 × 8 image. A scene that reads without
// errors must also survive formatScene and read back without errors (scene_writer.h's promise).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_support.h"
#include "render/strata_plan.h"
#include "scene/scene.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace trazo;
    if (size > fuzz::kMaxInputBytes) return 0;
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::string path = fuzz::sceneRoot() + "/fuzz.scene";
    Diagnostics diags;
    Scene scene = readSceneText(text, path, diags);
    static const bool verbose = std::getenv("TRAZO_FUZZ_VERBOSE") != nullptr;  // to check seeds: why refused
    if (verbose) printDiagnostics(diags);
    if (diags.hasErrors()) return 0;

    Diagnostics again;
    const std::string written = formatScene(scene, path);
    readSceneText(written, path, again);
    if (again.hasErrors()) {
        fuzz::fail("a scene that read without errors does not read back after formatScene: " +
                   formatDiagnostic(again.items.front()) + "\n--- written ---\n" + written);
    }

    if (!checkRenderBounds(scene, diags)) {
        if (verbose) printDiagnostics(diags);
        return 0;
    }
    scene.settings.renderWidth = scene.settings.renderHeight = 8;
    fuzz::renderTiny(scene);
    return 0;
}
