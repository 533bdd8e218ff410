// Undo and redo by snapshots. Each state the scene passes through gets an id, so "unsaved" is a comparison
// of ids, not of scenes.
#include "model/edit_history.h"

#include <utility>

namespace trazo {
namespace {

// The heap part of a string (libstdc++ keeps up to 15 characters inside the object).
size_t heapBytes(const std::string& s) { return s.capacity() > 15 ? s.capacity() + 1 : 0; }
size_t heapBytes(const SourceLocation& where) { return heapBytes(where.file); }

template <class T>
size_t vectorBytes(const std::vector<T>& v) {
    size_t bytes = v.capacity() * sizeof(T);
    for (const T& x : v) {
        bytes += heapBytes(x.where);
        if constexpr (requires { x.transforms; }) bytes += x.transforms.capacity() * sizeof(TransformStep);
        if constexpr (requires { x.source; }) bytes += heapBytes(x.source);
        if constexpr (requires { x.name; }) bytes += heapBytes(x.name);
    }
    return bytes;
}

}  // namespace

size_t snapshotBytes(const Scene& s) {
    const SceneSettings& t = s.settings;
    size_t bytes = sizeof(Scene) + heapBytes(s.path) + heapBytes(t.where) + heapBytes(t.reflectionQualityAt) +
                   heapBytes(t.reflectionStepsAt) + heapBytes(t.indirectQualityAt);
    bytes += vectorBytes(s.textures) + vectorBytes(s.materials);
#define TRAZO_X(Shape, array, ...) bytes += vectorBytes(s.array);
    TRAZO_OBJECT_KINDS(TRAZO_X)
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    for (const AreaLight& l : s.areaLights) bytes += heapBytes(l.subdivisionAt);
    return bytes;
}

EditHistory::EditHistory(size_t maxSteps, size_t maxBytes) : maxSteps_(maxSteps < 1 ? 1 : maxSteps), maxBytes_(maxBytes) {}

void EditHistory::push(std::deque<Step>& steps, Step step) {
    bytes_ += step.bytes;
    steps.push_back(std::move(step));
    // Past a bound, the oldest undo steps go (redo never holds more than undo held).
    while (undo_.size() > 1 && (undo_.size() > maxSteps_ || bytes_ > maxBytes_)) {
        bytes_ -= undo_.front().bytes;
        undo_.pop_front();
    }
}

void EditHistory::commit(const Scene& before, std::string label, DirtyFlags changed, uint64_t gesture) {
    for (const Step& s : redo_) bytes_ -= s.bytes;
    redo_.clear();
    const bool grows = gesture != 0 && gesture == gesture_ && !undo_.empty();
    gesture_ = gesture;
    if (grows) {
        undo_.back().changed |= changed;  // the step's `before` stays the scene at the gesture's start
    } else {
        push(undo_, Step{before, std::move(label), changed, current_, snapshotBytes(before)});
    }
    current_ = nextState_++;
}

DirtyFlags EditHistory::swap(std::deque<Step>& from, std::deque<Step>& to, Scene& current) {
    if (from.empty()) return kDirtyNone;
    gesture_ = 0;
    Step step = std::move(from.back());
    bytes_ -= step.bytes;
    from.pop_back();
    // The current scene becomes the opposite step: same label and changes, the state it is.
    const size_t currentBytes = snapshotBytes(current);
    Step opposite{std::move(current), step.label, step.changed, current_, currentBytes};
    current = std::move(step.scene);
    current.path = opposite.scene.path;  // where the scene is saved is no edit
    if (!(step.changed & kDirtyCamera)) current.camera = opposite.scene.camera;
    current_ = step.state;
    // A step that changed only how the image is shown (Exposure, ViewTransform) keeps the accumulation.
    DirtyFlags dirty = step.changed == kDirtyDisplay ? kDirtyDisplay
                                                     : kDirtyScene | (step.changed & (kDirtyCamera | kDirtySize));
    if (current.settings.renderWidth != opposite.scene.settings.renderWidth ||
        current.settings.renderHeight != opposite.scene.settings.renderHeight)
        dirty |= kDirtySize;
    bytes_ += opposite.bytes;
    to.push_back(std::move(opposite));
    return dirty;
}

DirtyFlags EditHistory::undo(Scene& current) { return swap(undo_, redo_, current); }
DirtyFlags EditHistory::redo(Scene& current) { return swap(redo_, undo_, current); }

std::string EditHistory::undoLabel() const { return undo_.empty() ? std::string() : undo_.back().label; }
std::string EditHistory::redoLabel() const { return redo_.empty() ? std::string() : redo_.back().label; }

void EditHistory::markSaved() {
    saved_ = current_;
    gesture_ = 0;
}

void EditHistory::reset(bool saved) {
    undo_.clear();
    redo_.clear();
    bytes_ = 0;
    gesture_ = 0;
    current_ = nextState_++;
    saved_ = saved ? current_ : 0;
}

}  // namespace trazo
