// The convergence plot: drawn with ImGui's draw list (PlotLines spaces its values evenly; these are not),
// log10 of the error up, seconds across, with the first and last values and the target marked.
#include "view/convergence_plot.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace trazo {

void drawConvergencePlot(const std::vector<std::pair<double, double>>& series, double target) {
    const float width = std::max(ImGui::GetContentRegionAvail().x, 60.0f);
    const ImVec2 size(width, 4.0f * ImGui::GetFontSize());
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("convergence", size);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(p0, ImVec2(p0.x + size.x, p0.y + size.y), ImGui::GetColorU32(ImGuiCol_FrameBg));

    double t1 = 0, lo = 1e30, hi = -1e30;
    for (const auto& [t, e] : series) {
        if (e <= 0) continue;
        t1 = std::max(t1, t);
        lo = std::min(lo, std::log10(e));
        hi = std::max(hi, std::log10(e));
    }
    if (target > 0) {
        lo = std::min(lo, std::log10(target));
        hi = std::max(hi, std::log10(target));
    }
    if (hi < lo) return;  // nothing positive to plot
    lo = std::floor(lo);  // whole decades: the scale reads at a glance
    hi = std::max(std::ceil(hi), lo + 1);
    t1 = std::max(t1, 1e-3);
    const auto at = [&](double t, double e) {
        return ImVec2(p0.x + float(t / t1) * (size.x - 1), p0.y + float((hi - std::log10(e)) / (hi - lo)) * (size.y - 1));
    };
    if (target > 0) {
        const float y = at(0, target).y;
        draw->AddLine(ImVec2(p0.x, y), ImVec2(p0.x + size.x, y), IM_COL32(120, 200, 120, 200));
    }
    ImVec2 last{};
    bool first = true;
    for (const auto& [t, e] : series) {
        if (e <= 0) continue;
        const ImVec2 p = at(t, e);
        if (!first) draw->AddLine(last, p, ImGui::GetColorU32(ImGuiCol_PlotLines), 1.5f);
        last = p;
        first = false;
    }
    if (!first) draw->AddCircleFilled(last, 2.5f, ImGui::GetColorU32(ImGuiCol_PlotLines));  // the latest estimate
    char label[64];
    std::snprintf(label, sizeof label, "1e%+.0f", hi);
    draw->AddText(ImVec2(p0.x + 2, p0.y), ImGui::GetColorU32(ImGuiCol_TextDisabled), label);
    std::snprintf(label, sizeof label, "1e%+.0f  %.1f s", lo, t1);
    draw->AddText(ImVec2(p0.x + 2, p0.y + size.y - ImGui::GetFontSize()), ImGui::GetColorU32(ImGuiCol_TextDisabled),
                  label);
}

}  // namespace trazo
