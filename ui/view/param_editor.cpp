// Parameter widgets in ImGui: the kinds of param_widget.h drawn over a row's values.
#include "view/param_editor.h"

#include <imgui.h>

namespace trazo {

void startGestures(Gestures& g) {
    g.edited = 0;
    if (!ImGui::IsAnyItemActive()) g.held = 0;  // released (however it was): the next grab is a new gesture
}

void trackGesture(Gestures& g, bool edited) {
    if (ImGui::IsItemActivated() || (edited && g.held == 0)) g.held = beginGesture(g);
    if (edited) g.edited = ImGui::IsItemActive() ? g.held : 0;
}

uint64_t heldGesture(Gestures& g) {
    if (!ImGui::IsAnyItemActive()) return 0;
    if (g.held == 0) g.held = beginGesture(g);
    return g.held;
}

bool comboIndex(const char* label, int32_t& index, const std::vector<std::string>& names, const char* noneLabel) {
    const char* none = noneLabel ? noneLabel : "";
    const char* preview = index >= 0 && size_t(index) < names.size() ? names[size_t(index)].c_str() : none;
    bool changed = false;
    if (ImGui::BeginCombo(label, preview)) {
        if (noneLabel && ImGui::Selectable(noneLabel, index < 0)) {
            changed = index != -1;
            index = -1;
        }
        for (size_t i = 0; i < names.size(); ++i) {
            ImGui::PushID(int(i));
            if (ImGui::Selectable(names[i].c_str(), index == int32_t(i))) {
                changed = index != int32_t(i);
                index = int32_t(i);
            }
            ImGui::PopID();
        }
        ImGui::EndCombo();
    }
    return changed;
}

bool drawParamWidget(const ParamInfo& info, const ParamWidget& w, ParamValue& v) {
    using Kind = ParamWidget::Kind;
    const std::string label(info.name);
    float f[4] = {v.real(0), v.real(1), v.real(2), v.real(3)};
    int n[2] = {v.integer(0), v.integer(1)};
    bool edited = false;
    switch (w.kind) {
        case Kind::None: return false;
        case Kind::Color:
            edited = ImGui::ColorEdit3(label.c_str(), f, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
            break;
        case Kind::Vector: edited = ImGui::DragFloat3(label.c_str(), f, w.speed); break;
        case Kind::Slider:
            edited = ImGui::SliderFloat(label.c_str(), f, float(w.min), float(w.max), w.format);
            break;
        case Kind::Drag:
            edited = ImGui::DragFloat(label.c_str(), f, w.speed, float(w.min), float(w.max), w.format);
            break;
        case Kind::Integer:
            edited = info.count == 2 ? ImGui::InputInt2(label.c_str(), n) : ImGui::InputInt(label.c_str(), n);
            if (w.commitOnExit) edited = ImGui::IsItemDeactivatedAfterEdit();
            break;
        case Kind::Choice: {
            const int choices[] = {1, 4, 16};
            int choice = n[0] == 16 ? 2 : n[0] == 4 ? 1 : 0;
            edited = ImGui::Combo(label.c_str(), &choice, "1\0" "4\0" "16\0");
            n[0] = choices[choice];
            break;
        }
        case Kind::Turn:  // a turn on the slider; Ctrl+click types any angle (the reader bounds none)
            edited = ImGui::SliderFloat(label.c_str(), f, -kTurnDegrees, kTurnDegrees, w.format);
            break;
        case Kind::Words: {
            std::vector<std::string> words(info.choices.begin(), info.choices.end());
            int32_t index = -1;
            for (size_t i = 0; i < words.size(); ++i)
                if (words[i] == v.text) index = int32_t(i);
            if (!comboIndex(label.c_str(), index, words, w.defaultLabel)) return false;
            v.text = index >= 0 ? words[size_t(index)] : std::string();
            return true;
        }
    }
    if (!edited) return false;
    for (int i = 0; i < info.count; ++i)
        v.numbers[size_t(i)] = info.kind == ValueKind::Int ? double(n[i]) : double(f[i]);
    return true;
}

}  // namespace trazo
