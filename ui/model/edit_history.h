// EditHistory: undo and redo of the viewer's scene edits (host, no UI), as whole-scene snapshots. A Scene
// copies cheaply: meshes and CSG trees are shared, so a snapshot holds the objects' parameters, not their
// triangles. Restoring a snapshot is exact, where moving back by −delta may round (scene_edit_test).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>

#include "model/dirty_flags.h"
#include "scene/scene.h"

namespace trazo {

// About what one snapshot of `scene` holds in memory: its vectors and strings, not the shared mesh and CSG
// data nor the textures' images (shared too).
size_t snapshotBytes(const Scene& scene);

class EditHistory {
public:
    // At most `maxSteps` undo steps, and at most about `maxBytes` of snapshots (snapshotBytes); the oldest
    // steps go first. At least one step is always kept.
    explicit EditHistory(size_t maxSteps = 200, size_t maxBytes = size_t(256) << 20);

    // Records an edit just made: `before` is the scene as it was, `changed` what the edit changed (the
    // panels' DirtyFlags). Consecutive commits with the same non-zero `gesture` (one held drag or slider)
    // make one step, labelled by the first; undo, redo and markSaved end a gesture. Clears redo.
    void commit(const Scene& before, std::string label, DirtyFlags changed, uint64_t gesture = 0);

    // Puts back the scene before the last step (redo: after the next undone one). The camera is put back
    // only when the step changed it (kDirtyCamera), so orbiting between edits is kept; the scene's path
    // (where it is saved) is never changed. Returns what to redo in the viewer: kDirtyScene, plus the step's
    // kDirtyCamera and kDirtySize; only kDirtyDisplay for a step that changed only that (Exposure,
    // ViewTransform); kDirtyNone when there was nothing to undo (redo).
    DirtyFlags undo(Scene& current);
    DirtyFlags redo(Scene& current);
    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    std::string undoLabel() const;  // "" when there is none
    std::string redoLabel() const;
    size_t undoSteps() const { return undo_.size(); }
    size_t redoSteps() const { return redo_.size(); }
    size_t bytes() const { return bytes_; }  // snapshotBytes of every snapshot held

    // Whether the current state differs from the one at the last markSaved() (or reset()); undoing or
    // redoing back to that state makes it saved again.
    bool unsaved() const { return current_ != saved_; }
    void markSaved();
    // Forgets every step (another scene opened); `saved`: the scene equals its file (false for one
    // recovered from a recovery file).
    void reset(bool saved = true);

private:
    struct Step {
        Scene scene;         // undo: the state before the step; redo: the state after it
        std::string label;
        DirtyFlags changed;
        uint64_t state;      // the id of the state `scene` is
        size_t bytes;
    };
    void push(std::deque<Step>& steps, Step step);
    DirtyFlags swap(std::deque<Step>& from, std::deque<Step>& to, Scene& current);

    size_t maxSteps_, maxBytes_;
    std::deque<Step> undo_, redo_;
    size_t bytes_ = 0;
    uint64_t current_ = 0, saved_ = 0, nextState_ = 1;
    uint64_t gesture_ = 0;  // the gesture the newest undo step may still grow by; 0 = none
};

}  // namespace trazo
