// ExportController: the viewer's file names and saving (host, no GL): the screenshot's name (a timestamped
// default, used once, or the one typed), the edited scene's name, and the status line each save leaves.
#pragma once

#include <ctime>
#include <string>

#include "model/panel_state.h"
#include "model/viewer_session.h"
#include "scene/scene.h"

namespace trazo {

// trazo-YYYYMMDD-HHMMSS.EXT for the local time `when`, with -2, -3… when that name exists in `folder` already
// (a bare name: relative to the current folder, as the viewer saves).
std::string timestampedName(const std::string& extension, std::time_t when, const std::string& folder = "");
// SCENE-edited.scene beside SCENE.
std::string editedScenePath(const std::string& scenePath);

// Writes the session's image to `path` as the viewer shows it (SPEC §7 Image: the scene's Exposure and
// ViewTransform, displayTransformOf; 8-bit files: the bytes shown; float files: the exposed value, linear):
// "saved PATH (N passes)" in `message`, or writeImage's reason.
bool saveSessionImage(ViewerSession& session, const std::string& path, std::string& message);

// Acts on the Export panel's fields (PanelState::screenshotPath, scenePath, status).
class ExportController {
public:
    // Fills the fields: the image name `screenshot` (a timestamped .png when empty) and SCENE-edited.scene.
    ExportController(const std::string& scenePath, const std::string& screenshot, PanelState& state);

    // "New name": a fresh default, with the extension the field has (.png when none).
    void renameScreenshot(PanelState& state);
    // Saves the image under the field's name; the status line (also on stderr) says how it went. A default
    // name is used once: the field then gets a fresh one (a typed name stays).
    void saveScreenshot(ViewerSession& session, PanelState& state);
    // Writes the edited scene under the field's name; the status line as for saveScreenshot. False when the
    // write failed.
    bool saveScene(const Scene& scene, PanelState& state);

private:
    void showDefault(const std::string& extension, PanelState& state);

    std::string defaultName_;  // the timestamped default in the Image field, while the user keeps it
};

}  // namespace trazo
