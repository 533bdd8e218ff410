// The viewer's run-time open: the start's checks, the diagnostics kept as text for the panel.
#include "model/scene_opener.h"

#include "render/strata_plan.h"
#include "scene/scene_reader.h"

namespace trazo {

OpenedScene openSceneFile(const std::string& path) {
    OpenedScene out;
    Diagnostics diags;
    Scene scene = readSceneFile(path, diags);
    if (!diags.hasErrors()) checkRenderBounds(scene, diags);  // as at start: no grid the kernels cannot count
    for (const Diagnostic& d : diags.items) out.messages.push_back(formatDiagnostic(d));
    if (!diags.hasErrors()) out.scene = std::move(scene);
    return out;
}

}  // namespace trazo
