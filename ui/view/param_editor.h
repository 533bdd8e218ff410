// ImGui editing of parameter rows (host): one widget per number row of a block table (widgetFor picks it and
// its limits), applied through the row so a value the reader would refuse is never set; a combo over names;
// and gesture ids that tell one held drag from the next, so the edit history makes each drag one undo step.
// The templates need no ImGui here: the widgets are drawn in param_editor.cpp.
#pragma once

#include <cstdint>
#include <span>
#include <string>
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

// A widget for every number row of `table` (names, paths and transforms have none), kept inside the reader's
// checks (fitToCheck); each change applied through the row and flagged as `flag` (a render size as size).
template <class Target>
DirtyFlags editRows(std::span<const ParamSpec<Target>> table, Target& target, DirtyFlags flag,
                    Gestures* gestures = nullptr) {
    DirtyFlags dirty = kDirtyNone;
    for (const ParamSpec<Target>& row : table) {
        const ParamWidget w = widgetFor(row.info);
        std::vector<ParamValue> values;
        row.extract(target, values);
        if (w.kind == ParamWidget::Kind::None || values.size() != 1) continue;
        ParamValue v = values[0];
        const bool edited = drawParamWidget(row.info, w, v) && fitToCheck(row.info, v) && v.numbers != values[0].numbers;
        if (gestures) trackGesture(*gestures, edited);
        if (!edited) continue;
        row.apply(target, v);
        dirty |= w.commitOnExit ? kDirtySize : flag;
    }
    return dirty;
}

}  // namespace trazo
