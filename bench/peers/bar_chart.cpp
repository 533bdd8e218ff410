// bar_chart: grouped bars from a CSV, on the renderer's plot axes (log y by default), written as a PNG (host).
//   bar_chart IN.csv OUT.png [--title T] [--ylabel L] [--xlabel L] [--linear]
// IN.csv: a header "label,Series 1,Series 2,…", then one row per group; an empty or non-positive value draws
// no bar. Groups are numbered 1…N under the axis (the label column is for the reader of the CSV; the plot
// font has no lower case and no room for long names). drawPlot gives the frame, grid and tick labels; the
// bars, group numbers and legend are filled in here with its font (plot_font.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "image/image_writer.h"
#include "support/plot.h"
#include "support/plot_font.h"

namespace {

using trazo::Vec3;

constexpr int kScale = 2;  // font pixels per glyph pixel, as the plot's own labels
const Vec3 kPalette[] = {{0.35f, 0.35f, 0.35f}, {0.85f, 0.33f, 0.10f}, {0.00f, 0.45f, 0.74f},
                         {0.47f, 0.67f, 0.19f}, {0.49f, 0.18f, 0.56f}};

struct Table {
    std::vector<std::string> series;
    std::vector<std::string> labels;
    std::vector<std::vector<double>> values;  // [group][series], NaN when absent
};

std::vector<std::string> splitCsv(const std::string& line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (char c : line) {
        if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) out.emplace_back();
        else if (c != '\r') out.back() += c;
    }
    return out;
}

bool readTable(const std::string& path, Table& t) {
    std::ifstream in(path);
    std::string line;
    if (!std::getline(in, line)) return false;
    const std::vector<std::string> header = splitCsv(line);
    t.series.assign(header.begin() + 1, header.end());
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        const std::vector<std::string> cells = splitCsv(line);
        t.labels.push_back(cells[0]);
        std::vector<double>& row = t.values.emplace_back(t.series.size(), NAN);
        for (size_t s = 0; s < t.series.size() && s + 1 < cells.size(); ++s) {
            char* end = nullptr;
            const double v = std::strtod(cells[s + 1].c_str(), &end);
            if (end != cells[s + 1].c_str()) row[s] = v;
        }
    }
    return !t.series.empty() && !t.values.empty();
}

struct Painter {
    trazo::PlotImage& img;
    void fill(int x0, int y0, int x1, int y1, Vec3 c) {
        for (int y = std::max(y0, 0); y < std::min(y1, img.height); ++y)
            for (int x = std::max(x0, 0); x < std::min(x1, img.width); ++x) img.pixels[(size_t)y * img.width + x] = c;
    }
    static int textWidth(const std::string& s) { return (int)s.size() * (trazo::kGlyphWidth + 1) * kScale - kScale; }
    void text(int x, int y, const std::string& s, Vec3 c) {
        for (size_t i = 0; i < s.size(); ++i) {
            const trazo::Glyph* g = trazo::findGlyph(s[i]);
            if (!g) continue;
            for (int gy = 0; gy < trazo::kGlyphHeight; ++gy)
                for (int gx = 0; gx < trazo::kGlyphWidth; ++gx)
                    if (g->rows[gy][gx] == '#') {
                        const int u = x + ((int)i * (trazo::kGlyphWidth + 1) + gx) * kScale, v = y + gy * kScale;
                        fill(u, v, u + kScale, v + kScale, c);
                    }
        }
    }
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: bar_chart IN.csv OUT.png [--title T] [--ylabel L] [--xlabel L] [--linear]\n");
        return 2;
    }
    trazo::PlotSpec spec;
    spec.logX = false;
    spec.xLabel = "row";
    for (int i = 3; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--linear") spec.logY = false;
        else if (i + 1 < argc && a == "--title") spec.title = argv[++i];
        else if (i + 1 < argc && a == "--ylabel") spec.yLabel = argv[++i];
        else if (i + 1 < argc && a == "--xlabel") spec.xLabel = argv[++i];
        else return std::fprintf(stderr, "bar_chart: unknown option %s\n", a.c_str()), 2;
    }
    Table t;
    if (!readTable(argv[1], t)) return std::fprintf(stderr, "bar_chart: cannot read a table from %s\n", argv[1]), 2;

    // Invisible series (no line, no marker, no legend entry) fit the y axis to the data; bars go on top.
    const int groups = (int)t.values.size(), series = (int)t.series.size();
    for (int s = 0; s < series; ++s) {
        trazo::PlotSeries ps;
        ps.lines = ps.markers = false;
        for (int g = 0; g < groups; ++g) ps.x.push_back(g + 1), ps.y.push_back(t.values[g][s]);
        spec.series.push_back(ps);
    }
    spec.width = std::max(900, 60 * groups + 200);
    spec.xMin = 0.5, spec.xMax = groups + 0.5;
    trazo::PlotImage img = trazo::drawPlot(spec);
    const trazo::PlotFrame& f = img.frame;
    Painter paint{img};

    const double baseY = f.bottom - 1, slot = 0.8 / series;
    for (int g = 0; g < groups; ++g)
        for (int s = 0; s < series; ++s) {
            const double v = t.values[g][s];
            if (!std::isfinite(v) || (spec.logY && v <= 0)) continue;
            const double left = g + 1 - 0.4 + s * slot;
            const int x0 = (int)std::lround(f.pixelX(left)), x1 = (int)std::lround(f.pixelX(left + slot)) - 1;
            const int top = (int)std::lround(std::clamp(f.pixelY(v), (double)f.top, baseY));
            paint.fill(x0, top, std::max(x1, x0 + 1), (int)baseY + 1, kPalette[s % 5]);
        }
    // Replace the x tick labels by one number per group.
    const int th = trazo::kGlyphHeight * kScale;
    paint.fill(f.left - 40, f.bottom + 7, f.right + 40, f.bottom + 10 + th + 1, Vec3(1.0f));
    for (int g = 0; g < groups; ++g) {
        const std::string s = std::to_string(g + 1);
        paint.text((int)std::lround(f.pixelX(g + 1)) - Painter::textWidth(s) / 2, f.bottom + 10, s, Vec3(0.0f));
    }
    // Legend, top left inside the plot area.
    int longest = 0;
    for (const std::string& s : t.series) longest = std::max(longest, Painter::textWidth(s));
    const int bx = f.left + 10, by = f.top + 10, lineH = th + 8, boxW = longest + 48, boxH = series * lineH + 10;
    paint.fill(bx, by, bx + boxW, by + boxH, Vec3(0.0f));
    paint.fill(bx + 1, by + 1, bx + boxW - 1, by + boxH - 1, Vec3(1.0f));
    for (int s = 0; s < series; ++s) {
        const int y = by + 6 + s * lineH;
        paint.fill(bx + 8, y, bx + 32, y + th, kPalette[s % 5]);
        paint.text(bx + 40, y, t.series[s], Vec3(0.0f));
    }

    std::string error;
    if (!trazo::writeImage(argv[2], img.width, img.height, img.pixels, error))
        return std::fprintf(stderr, "bar_chart: %s\n", error.c_str()), 1;
    return 0;
}
