// The viewer's widget for one parameter row (host, no ImGui): its kind from the row's value kind and unit, its
// limits from the row's range (editRange), so a panel cannot set a value the reader would refuse.
#pragma once

#include "scene/param_check.h"

namespace trazo {

struct ParamWidget {
    enum class Kind { None, Color, Vector, Slider, Drag, Integer, Choice } kind = Kind::None;
    double min = 0, max = 0;  // every value, inclusive (editRange)
    float speed = 0.01f;      // drags: change per pixel
    const char* format = "%.3f";
    bool commitOnExit = false;  // RenderSize: a new size reallocates, so it applies when the field is left
};

// Sliders for ranges a slider can span (both ends finite and short); drags for the rest.
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
    if (info.kind != ValueKind::Real) return w;
    if (info.unit == ValueUnit::Degrees) w.format = "%.1f°";
    if (info.unit == ValueUnit::Radians) w.format = "%.3f rad";
    if (info.count == 3 && !info.accumulates) {
        w.kind = info.unit == ValueUnit::Color ? Kind::Color : Kind::Vector;
        w.speed = info.check == ValueCheck::NonZeroVector ? 0.01f : 0.05f;
    } else if (info.count == 1) {
        w.kind = range.max - range.min <= 180 ? Kind::Slider : Kind::Drag;
    }
    return w;
}

}  // namespace trazo
