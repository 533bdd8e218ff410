// The Render panel's plot of the estimated relative error against render time, on a log scale (ImGui only).
#pragma once

#include <utility>
#include <vector>

namespace trazo {

// `series`: (seconds since the reset, relative error), in time order. A positive `target` is drawn as a line.
void drawConvergencePlot(const std::vector<std::pair<double, double>>& series, double target);

}  // namespace trazo
