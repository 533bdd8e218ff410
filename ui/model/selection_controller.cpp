// SelectionController: picking, the log line, and the outline from the session's per-pixel object ids.
#include "model/selection_controller.h"

#include <cstdio>
#include <filesystem>

#include "model/selection_outline.h"

namespace trazo {

std::string selectionName(const Scene& scene, ObjectId id) {
    const SourceLocation& where = objectWhere(scene, id);
    const std::string place = where.file.empty()
                                  ? std::string("added")
                                  : std::filesystem::path(where.file).filename().string() + ":" + std::to_string(where.line);
    return std::string(kindKeyword(id.kind)) + " " + std::to_string(id.index) + " (" + place + ")";
}

void SelectionController::click(ViewerSession& session, Selection& selection, ImagePoint p) {
    const std::optional<PickHit> hit = session.pick(p.x, p.y);
    selection = hit ? Selection(hit->object) : std::nullopt;
    report(session.scene(), selection);
}

void SelectionController::report(const Scene& scene, const Selection& selection) {
    if (selection == logged_) return;
    logged_ = selection;
    if (selection) std::fprintf(stderr, "trazo: selected %s\n", selectionName(scene, *selection).c_str());
    else std::fprintf(stderr, "trazo: selection cleared\n");
}

bool SelectionController::refreshOutline(ViewerSession& session, const Selection& selection,
                                         std::vector<uint8_t>& outline) {
    if (selection != outlined_) stale_ = true;
    if (!stale_) return false;
    if (!selection) {
        stale_ = false;
        outlined_ = selection;
        const bool had = !outline.empty();
        outline.clear();
        return had;
    }
    // Wait for the full-size image of the current scene (while the user drags, the outline is hidden).
    if (session.busy() || session.dirty() != kDirtyNone || session.previewDivisor() != 1 ||
        session.accumulation().passes() == 0) {
        const bool had = !outline.empty();
        outline.clear();
        return had;
    }
    const uint32_t w = session.renderWidth(), h = session.renderHeight();
    outline = outlineOf(session.selectionMask(session.objectIds(w, h), *selection), w, h);
    outlined_ = selection;
    stale_ = false;
    return true;
}

}  // namespace trazo
