// SelectionController: what a click on the image selects (the renderer's own ray query, ViewerSession::pick),
// the line each change of the selection leaves on stderr ("trazo: selected Sphere 1 (two.scene:9)"), and the
// selection's outline for the display, refreshed once the full-size image shows the current scene. No GL.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/object_commands.h"
#include "model/image_placement.h"
#include "model/viewer_session.h"

namespace trazo {

// "Sphere 1 (two.scene:9)": the kind's keyword, its index, and where its block is ("added" for an object made
// in the viewer).
std::string selectionName(const Scene& scene, ObjectId id);

class SelectionController {
public:
    // A click at `p` (full-size image pixels): selects the object the camera ray through it hits first, or
    // clears the selection over the background.
    void click(ViewerSession& session, Selection& selection, ImagePoint p);
    // Logs the selection when it differs from the last one logged (a click, the Objects panel, an undo).
    void report(const Scene& scene, const Selection& selection);

    // The scene, the camera or the size changed: the outline is hidden until refreshed.
    void invalidate() { stale_ = true; }
    // When stale and the session shows a full-size image, recomputes the outline (the selected object's pixels'
    // edge, at the render size); true when `outline` changed (empty: nothing to draw).
    bool refreshOutline(ViewerSession& session, const Selection& selection, std::vector<uint8_t>& outline);

private:
    Selection logged_;
    Selection outlined_;
    bool stale_ = true;
};

}  // namespace trazo
