// The viewer's widget for one parameter row (host, no ImGui): its kind from the row's value kind and unit, its
// limits from the row's range (editRange), so a panel cannot set a value the reader would refuse; a Name row
// with a word list (Integrator, ViewTransform) gets a combo of its words.
#pragma once

#include "scene/param_check.h"
#include "scene/scene.h"

namespace trazo {

struct ParamWidget {
    // Choice: Antialiasing's 1, 4, 16. Words: one of ParamInfo::choices. Turn: an unbounded angle, a slider
    // over one turn (kTurnDegrees) that takes any value typed (Ctrl+click).
    enum class Kind { None, Color, Vector, Slider, Drag, Integer, Choice, Words, Turn } kind = Kind::None;
    double min = 0, max = 0;  // every value, inclusive (editRange)
    float speed = 0.01f;      // drags: change per pixel
    const char* format = "%.3f";
    bool commitOnExit = false;  // RenderSize: a new size reallocates, so it applies when the field is left
    // Words: the combo's first entry, for a default the table writes as nothing (null: the row always has a word).
    const char* defaultLabel = nullptr;
};

// The slider's span of a Turn widget: −180 … 180 degrees.
constexpr float kTurnDegrees = 180.0f;

// The combo entry of a Words row whose default is written as nothing (its value then depends on other
// settings): ViewTransform's Auto. Null for the others.
inline const char* unwrittenDefaultLabel(const ParamInfo& info) {
    if (info.name == "ViewTransform") return "auto (linear under thesis, srgb under path)";
    return nullptr;
}

// Puts such a row back to its unwritten default (what unwrittenDefaultLabel names); false for other rows.
inline bool resetToUnwrittenDefault(SceneSettings& settings, const ParamInfo& info) {
    if (info.name != "ViewTransform") return false;
    settings.viewTransform = ViewTransform::Auto;
    return true;
}
template <class Target>
bool resetToUnwrittenDefault(Target&, const ParamInfo&) {
    return false;
}

// Sliders for ranges a slider can span (both ends finite and short), a turn for an unbounded angle, drags for
// the rest; a combo for a word list.
inline ParamWidget widgetFor(const ParamInfo& info) {
    using Kind = ParamWidget::Kind;
    ParamWidget w;
    const ValueRange range = editRange(info);
    w.min = range.min;
    w.max = range.max;
    if (info.kind == ValueKind::Int) {
        w.kind = info.check == ValueCheck::Antialiasing ? Kind::Choice : Kind::Integer;
        w.commitOnExit = info.check == ValueCheck::RenderSize;
        return w;
    }
    if (info.kind == ValueKind::Name && !info.choices.empty()) {
        w.kind = Kind::Words;
        w.defaultLabel = unwrittenDefaultLabel(info);
        return w;
    }
    if (info.kind != ValueKind::Real) return w;
    if (info.unit == ValueUnit::Degrees) w.format = "%.1f°";
    if (info.unit == ValueUnit::Radians) w.format = "%.3f rad";
    if (info.count == 3 && !info.accumulates) {
        w.kind = info.unit == ValueUnit::Color ? Kind::Color : Kind::Vector;
        w.speed = info.check == ValueCheck::NonZeroVector ? 0.01f : 0.05f;
    } else if (info.count == 1) {
        const bool unboundedAngle = info.unit == ValueUnit::Degrees && range.max - range.min > 360;
        w.kind = unboundedAngle ? Kind::Turn : range.max - range.min <= 180 ? Kind::Slider : Kind::Drag;
    }
    return w;
}

}  // namespace trazo
