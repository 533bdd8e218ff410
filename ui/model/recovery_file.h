// RecoveryFile: the edited scene kept next to its file while it has unsaved edits (host, no UI), so that a
// crash or a kill loses at most the last second of edits. SCENE's recovery file is "SCENE.recovery" (e.g.
// scenes/scene1_area.scene.recovery), scene-language text in which relative paths resolve as in SCENE. It is
// written through a temporary renamed over it (io/atomic_file.h), so at any instant it is the previous
// complete version or the new one, never half of one.
#pragma once

#include <chrono>
#include <optional>
#include <string>

#include "scene/diagnostic.h"
#include "scene/scene.h"

namespace trazo {

class RecoveryFile {
public:
    using Clock = std::chrono::steady_clock;

    // For the scene file `scenePath` (an empty path: a scene that is no file; nothing is ever written).
    // Writes at most once every `interval`.
    explicit RecoveryFile(std::string scenePath, Clock::duration interval = std::chrono::seconds(1));

    static std::string pathFor(const std::string& scenePath);  // scenePath + ".recovery"
    // The recovery file an earlier session left for `scenePath`, if there is one.
    static std::optional<std::string> find(const std::string& scenePath);
    // A recovery file read back as the scene it keeps, with `path` set to the scene's own file; errors in
    // `diags` (then the result is meaningless).
    static Scene read(const std::string& scenePath, Diagnostics& diags);

    // Call every frame. With unsaved edits: writes the scene when `interval` has passed since the last
    // write and its text differs from what was written; without: removes the file (a clean save, or every
    // edit undone; only a file this object wrote, so one an earlier session left stays until the viewer
    // has asked about it). True when it wrote or removed the file. A failed write is kept in error() and retried at
    // the next interval.
    bool update(const Scene& scene, bool unsaved, Clock::time_point now = Clock::now()) {
        return write(scene, unsaved, false, now);
    }
    // The same without the rate limit (before something risky, on demand).
    bool flush(const Scene& scene, bool unsaved) { return write(scene, unsaved, true, Clock::now()); }
    // Removes the file: a quit without unsaved edits, or with edits the user chose to discard. (A crash or
    // kill calls nothing: the file stays for the next session's find.)
    void remove();

    const std::string& path() const { return path_; }
    const std::string& error() const { return error_; }  // the last failed write's reason; "" after a success

private:
    bool write(const Scene& scene, bool unsaved, bool force, Clock::time_point now);

    std::string scenePath_, path_;
    Clock::duration interval_;
    std::optional<Clock::time_point> lastWrite_;
    std::string written_;  // the text last written ("" when the file is not ours or was removed)
    bool exists_ = false;  // whether this object wrote the file and has not removed it
    std::string error_;
};

}  // namespace trazo
