// Line plots drawn into a pixel buffer (host): log or linear axes, decade ticks with labels, anti-aliased
// solid or dashed lines with point markers, a legend; written through writeImage (FreeImage). Used by the
// convergence benchmark for its time-versus-error curves.
#pragma once

#include <string>
#include <vector>

#include "core/vec3.h"

namespace trazo {

struct PlotSeries {
    std::string label;      // shown in the legend (empty: not listed)
    std::vector<double> x, y;
    Vec3 color{0.0f, 0.0f, 0.0f};
    bool dashed = false;
    bool markers = true;    // a dot at every data point
    bool lines = true;      // join the points
};

struct PlotSpec {
    int width = 900, height = 640;
    std::string title, xLabel, yLabel;
    bool logX = true, logY = true;
    std::vector<PlotSeries> series;
    // Axis ranges; when lo >= hi they are fitted to the data (log axes to whole decades).
    double xMin = 0, xMax = 0, yMin = 0, yMax = 0;
};

// Where data lands: the plot area in pixels and the axis ranges (in log10 units on a log axis).
struct PlotFrame {
    int left = 0, top = 0, right = 0, bottom = 0;  // plot area, pixel edges (right/bottom exclusive)
    double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
    bool logX = true, logY = true;
    // Pixel-centre coordinates (x right, y down) of a data point; pixel (i, j) has its centre at (i, j).
    double pixelX(double x) const;
    double pixelY(double y) const;
};

struct PlotImage {
    int width = 0, height = 0;
    std::vector<Vec3> pixels;  // linear RGB in [0, 1], row 0 = top
    PlotFrame frame;
    const Vec3& at(int x, int y) const { return pixels[(size_t)y * width + x]; }
};

PlotImage drawPlot(const PlotSpec& spec);
// drawPlot, then writeImage (format by extension; .png for a picture). False with a reason on failure.
bool writePlot(const std::string& path, const PlotSpec& spec, std::string& error);

// Tick label for a decade 10^k: "0.001" … "1000" for |k| <= 3, "1e-5" style beyond.
std::string decadeLabel(int k);

}  // namespace trazo
