// ImGui editing of parameter rows (host): one widget per number row of a block table (widgetFor picks it and
// its limits), applied through the row so a value the reader would refuse is never set; a combo over names;
// and gesture ids that tell one held drag from the next, so the edit history makes each drag one undo step.
// The templates need no ImGui here: the widgets are drawn in param_editor.cpp.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "model/dirty_flags.h"
#include "model/panel_state.h"
#include "model/param_widget.h"
#include "scene/param_spec.h"

namespace trazo {

// The widgets' side of Gestures (model/panel_state.h). Call at the start of a panel, every frame.
void startGestures(Gestures& g);
// Call right after a widget, with whether it changed its value.
void trackGesture(Gestures& g, bool edited);
// For panels that do not track their widgets: the gesture of whatever widget is held now (a new one when
// none was held at the last call since startGestures), 0 when none is held.
uint64_t heldGesture(Gestures& g);

// The widget of one row over `v` (which holds the edit); true when the user changed it.
bool drawParamWidget(const ParamInfo& info, const ParamWidget& w, ParamValue& v);
// A combo over names, with `noneLabel` as index −1 first when given; true when the choice changed.
bool comboIndex(const char* label, int32_t& index, const std::vector<std::string>& names, const char* noneLabel);

// A widget for every number row of `table` and every row with a word list (other names, paths and transforms
// have none), kept inside the reader's checks (fitToCheck); each change applied through the row (a word list's
// unwritten default through resetToUnwrittenDefault) and flagged as `effect`: DirtyFlags for every row, or a
// function of the row's ParamInfo (model/setting_effects.h); a render size as size.
template <class Target, class Effect>
DirtyFlags editRows(std::span<const ParamSpec<Target>> table, Target& target, Effect effect,
                    Gestures* gestures = nullptr) {
    DirtyFlags dirty = kDirtyNone;
    for (const ParamSpec<Target>& row : table) {
        const ParamWidget w = widgetFor(row.info);
        if (w.kind == ParamWidget::Kind::None) continue;
        std::vector<ParamValue> values;
        row.extract(target, values);
        // No value: a word list's default that is written as nothing (ViewTransform's auto).
        const bool unwritten = values.empty() && w.kind == ParamWidget::Kind::Words && w.defaultLabel;
        if (values.size() != 1 && !unwritten) continue;
        const ParamValue old = unwritten ? ParamValue{} : values[0];
        ParamValue v = old;
        const bool edited = drawParamWidget(row.info, w, v) && fitToCheck(row.info, v) &&
                            (v.numbers != old.numbers || v.text != old.text);
        if (gestures) trackGesture(*gestures, edited);
        if (!edited) continue;
        if (w.kind == ParamWidget::Kind::Words && v.text.empty()) {
            if (!resetToUnwrittenDefault(target, row.info)) continue;
        } else {
            row.apply(target, v);
        }
        if (w.commitOnExit) {
            dirty |= kDirtySize;
        } else if constexpr (std::is_invocable_r_v<DirtyFlags, Effect, const ParamInfo&>) {
            dirty |= effect(row.info);
        } else {
            dirty |= DirtyFlags(effect);
        }
    }
    return dirty;
}

}  // namespace trazo
