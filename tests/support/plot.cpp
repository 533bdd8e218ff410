// Plot rasterisation: coverage-based anti-aliased segments and dots, a 5×7 font scaled 2×, decade ticks.
#include "support/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "image/image_writer.h"
#include "support/plot_font.h"

namespace trazo {

namespace {

constexpr int kTextScale = 2;  // font pixels per glyph pixel
constexpr int kCharAdvance = (kGlyphWidth + 1) * kTextScale;
const Vec3 kWhite(1.0f), kBlack(0.0f), kGrid(0.86f), kMinorGrid(0.94f);

class Canvas {
public:
    Canvas(int w, int h) : w_(w), h_(h), pixels_((size_t)w * h, kWhite) {}

    void blend(int x, int y, Vec3 c, double alpha) {
        if (x < 0 || y < 0 || x >= w_ || y >= h_ || alpha <= 0.0) return;
        Vec3& p = pixels_[(size_t)y * w_ + x];
        p = lerp(p, c, (float)std::min(alpha, 1.0));
    }
    void fillRect(int x0, int y0, int x1, int y1, Vec3 c) {
        for (int y = std::max(y0, 0); y < std::min(y1, h_); ++y)
            for (int x = std::max(x0, 0); x < std::min(x1, w_); ++x) pixels_[(size_t)y * w_ + x] = c;
    }
    // A segment of the given width: each pixel takes the coverage of its centre's distance to the segment
    // (a 1-px box filter), so lines are anti-aliased at any slope. Dashes: on for `dashOn` px of arc length,
    // off for `dashOff`, measured from `arcStart`.
    void segment(double ax, double ay, double bx, double by, Vec3 c, double width, double arcStart = 0,
                 double dashOn = 0, double dashOff = 0) {
        const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy, len = std::sqrt(len2);
        const double half = 0.5 * width;
        const int x0 = (int)std::floor(std::min(ax, bx) - half - 1), x1 = (int)std::ceil(std::max(ax, bx) + half + 1);
        const int y0 = (int)std::floor(std::min(ay, by) - half - 1), y1 = (int)std::ceil(std::max(ay, by) + half + 1);
        for (int y = std::max(y0, clipTop); y <= std::min(y1, clipBottom); ++y) {
            for (int x = std::max(x0, clipLeft); x <= std::min(x1, clipRight); ++x) {
                double t = len2 > 0 ? ((x - ax) * dx + (y - ay) * dy) / len2 : 0.0;
                t = std::clamp(t, 0.0, 1.0);
                const double px = ax + t * dx - x, py = ay + t * dy - y;
                const double d = std::sqrt(px * px + py * py);
                double cover = std::clamp(half + 0.5 - d, 0.0, 1.0);
                if (dashOn > 0) {
                    const double s = std::fmod(arcStart + t * len, dashOn + dashOff);
                    cover *= std::clamp(std::min(s, dashOn - s) + 0.5, 0.0, 1.0);
                }
                if (cover > 0) blend(x, y, c, cover);
            }
        }
    }
    void dot(double cx, double cy, double radius, Vec3 c) {
        for (int y = (int)std::floor(cy - radius - 1); y <= (int)std::ceil(cy + radius + 1); ++y)
            for (int x = (int)std::floor(cx - radius - 1); x <= (int)std::ceil(cx + radius + 1); ++x) {
                if (x < clipLeft || x > clipRight || y < clipTop || y > clipBottom) continue;
                const double d = std::hypot(x - cx, y - cy);
                blend(x, y, c, std::clamp(radius + 0.5 - d, 0.0, 1.0));
            }
    }
    // Text with its top-left at (x, y); vertical text runs bottom to top with its baseline towards x.
    void text(int x, int y, const std::string& s, Vec3 c, bool vertical = false) {
        for (size_t i = 0; i < s.size(); ++i) {
            const Glyph* g = findGlyph(s[i]);
            if (!g) continue;
            for (int gy = 0; gy < kGlyphHeight; ++gy)
                for (int gx = 0; gx < kGlyphWidth; ++gx) {
                    if (g->rows[gy][gx] != '#') continue;
                    const int u = (int)i * kCharAdvance + gx * kTextScale, v = gy * kTextScale;
                    for (int sy = 0; sy < kTextScale; ++sy)
                        for (int sx = 0; sx < kTextScale; ++sx) {
                            if (vertical) blend(x + v + sy, y - u - sx, c, 1.0);
                            else blend(x + u + sx, y + v + sy, c, 1.0);
                        }
                }
        }
    }
    static int textWidth(const std::string& s) { return (int)s.size() * kCharAdvance - kTextScale; }
    static int textHeight() { return kGlyphHeight * kTextScale; }

    std::vector<Vec3> take() { return std::move(pixels_); }
    int clipLeft = 0, clipTop = 0, clipRight = 1 << 30, clipBottom = 1 << 30;

private:
    int w_, h_;
    std::vector<Vec3> pixels_;
};

struct Range {
    double lo = 0, hi = 0;
};

Range dataRange(const PlotSpec& spec, bool xAxis, bool logAxis) {
    Range r{INFINITY, -INFINITY};
    for (const PlotSeries& s : spec.series)
        for (double v : xAxis ? s.x : s.y) {
            if (!std::isfinite(v) || (logAxis && v <= 0)) continue;
            const double u = logAxis ? std::log10(v) : v;
            r.lo = std::min(r.lo, u);
            r.hi = std::max(r.hi, u);
        }
    if (!(r.lo <= r.hi)) return {0, 1};
    if (logAxis) {
        r.lo = std::floor(r.lo + 1e-9);
        r.hi = std::ceil(r.hi - 1e-9);
        if (r.hi <= r.lo) r.hi = r.lo + 1;
    } else {
        const double pad = r.hi > r.lo ? 0.05 * (r.hi - r.lo) : 1.0;
        r.lo -= pad;
        r.hi += pad;
    }
    return r;
}

Range axisRange(double lo, double hi, const PlotSpec& spec, bool xAxis, bool logAxis) {
    if (lo < hi && (!logAxis || lo > 0)) return logAxis ? Range{std::log10(lo), std::log10(hi)} : Range{lo, hi};
    return dataRange(spec, xAxis, logAxis);
}

std::string linearLabel(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", std::fabs(v) < 1e-12 ? 0.0 : v);
    return buf;
}

}  // namespace

double PlotFrame::pixelX(double x) const {
    const double u = logX ? std::log10(x) : x;
    return left + (u - x0) / (x1 - x0) * (right - 1 - left);
}

double PlotFrame::pixelY(double y) const {
    const double u = logY ? std::log10(y) : y;
    return bottom - 1 - (u - y0) / (y1 - y0) * (bottom - 1 - top);
}

std::string decadeLabel(int k) {
    if (k >= 0 && k <= 3) return std::to_string((int)std::lround(std::pow(10.0, k)));
    if (k < 0 && k >= -3) return "0." + std::string(-k - 1, '0') + "1";
    return "1e" + std::to_string(k);
}

PlotImage drawPlot(const PlotSpec& spec) {
    PlotImage img;
    img.width = std::max(spec.width, 200);
    img.height = std::max(spec.height, 150);
    Canvas cv(img.width, img.height);

    PlotFrame& f = img.frame;
    f.logX = spec.logX;
    f.logY = spec.logY;
    const Range rx = axisRange(spec.xMin, spec.xMax, spec, true, spec.logX);
    const Range ry = axisRange(spec.yMin, spec.yMax, spec, false, spec.logY);
    f.x0 = rx.lo, f.x1 = rx.hi, f.y0 = ry.lo, f.y1 = ry.hi;
    const int th = Canvas::textHeight();
    f.left = 30 + th + 8 * kCharAdvance;  // y label, then tick labels up to 7 characters
    f.right = img.width - 20;
    f.top = spec.title.empty() ? 16 : 20 + th + 12;
    f.bottom = img.height - (20 + 2 * th + 16);

    // Grid and ticks: decades (and 2…9 minor lines) on log axes, about 8 steps on linear ones.
    auto ticks = [](double lo, double hi, bool logAxis, std::vector<double>& major, std::vector<double>& minor) {
        if (logAxis) {
            for (int k = (int)std::ceil(lo - 1e-9); k <= (int)std::floor(hi + 1e-9); ++k) major.push_back(k);
            for (int k = (int)std::floor(lo); k <= (int)std::ceil(hi); ++k)
                for (int m = 2; m <= 9; ++m) {
                    const double u = k + std::log10((double)m);
                    if (u > lo && u < hi) minor.push_back(u);
                }
        } else {
            const double raw = (hi - lo) / 8, mag = std::pow(10.0, std::floor(std::log10(raw)));
            const double step = raw / mag < 2 ? 2 * mag : (raw / mag < 5 ? 5 * mag : 10 * mag);
            for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) major.push_back(v);
        }
    };
    std::vector<double> xMajor, xMinor, yMajor, yMinor;
    ticks(f.x0, f.x1, f.logX, xMajor, xMinor);
    ticks(f.y0, f.y1, f.logY, yMajor, yMinor);
    auto px = [&](double u) { return f.left + (u - f.x0) / (f.x1 - f.x0) * (f.right - 1 - f.left); };
    auto py = [&](double u) { return f.bottom - 1 - (u - f.y0) / (f.y1 - f.y0) * (f.bottom - 1 - f.top); };
    for (double u : xMinor) cv.fillRect((int)std::lround(px(u)), f.top, (int)std::lround(px(u)) + 1, f.bottom, kMinorGrid);
    for (double u : yMinor) cv.fillRect(f.left, (int)std::lround(py(u)), f.right, (int)std::lround(py(u)) + 1, kMinorGrid);
    for (double u : xMajor) {
        const int x = (int)std::lround(px(u));
        cv.fillRect(x, f.top, x + 1, f.bottom, kGrid);
        cv.fillRect(x, f.bottom, x + 1, f.bottom + 6, kBlack);
        const std::string s = f.logX ? decadeLabel((int)std::lround(u)) : linearLabel(u);
        cv.text(x - Canvas::textWidth(s) / 2, f.bottom + 10, s, kBlack);
    }
    for (double u : yMajor) {
        const int y = (int)std::lround(py(u));
        cv.fillRect(f.left, y, f.right, y + 1, kGrid);
        cv.fillRect(f.left - 6, y, f.left, y + 1, kBlack);
        const std::string s = f.logY ? decadeLabel((int)std::lround(u)) : linearLabel(u);
        cv.text(f.left - 10 - Canvas::textWidth(s), y - th / 2, s, kBlack);
    }
    // Frame.
    cv.fillRect(f.left - 1, f.top - 1, f.right + 1, f.top, kBlack);
    cv.fillRect(f.left - 1, f.bottom, f.right + 1, f.bottom + 1, kBlack);
    cv.fillRect(f.left - 1, f.top - 1, f.left, f.bottom + 1, kBlack);
    cv.fillRect(f.right, f.top - 1, f.right + 1, f.bottom + 1, kBlack);

    // Series, clipped to the plot area.
    cv.clipLeft = f.left, cv.clipTop = f.top, cv.clipRight = f.right - 1, cv.clipBottom = f.bottom - 1;
    for (const PlotSeries& s : spec.series) {
        double arc = 0, lastX = 0, lastY = 0;
        bool have = false;
        for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
            const bool ok = std::isfinite(s.x[i]) && std::isfinite(s.y[i]) && (!f.logX || s.x[i] > 0) &&
                            (!f.logY || s.y[i] > 0);
            if (!ok) {
                have = false;
                continue;
            }
            const double x = f.pixelX(s.x[i]), y = f.pixelY(s.y[i]);
            if (have && s.lines) {
                cv.segment(lastX, lastY, x, y, s.color, 2.0, arc, s.dashed ? 9.0 : 0.0, 6.0);
                arc += std::hypot(x - lastX, y - lastY);
            }
            if (s.markers) cv.dot(x, y, 3.0, s.color);
            lastX = x, lastY = y, have = true;
        }
    }
    cv.clipLeft = 0, cv.clipTop = 0, cv.clipRight = 1 << 30, cv.clipBottom = 1 << 30;

    // Legend (top right, inside the plot area).
    int entries = 0, longest = 0;
    for (const PlotSeries& s : spec.series)
        if (!s.label.empty()) ++entries, longest = std::max(longest, Canvas::textWidth(s.label));
    if (entries > 0) {
        const int lineH = th + 8, boxW = longest + 56, boxH = entries * lineH + 10;
        const int bx = f.right - boxW - 10, by = f.top + 10;
        cv.fillRect(bx, by, bx + boxW, by + boxH, kWhite);
        cv.fillRect(bx, by, bx + boxW, by + 1, kBlack);
        cv.fillRect(bx, by + boxH - 1, bx + boxW, by + boxH, kBlack);
        cv.fillRect(bx, by, bx + 1, by + boxH, kBlack);
        cv.fillRect(bx + boxW - 1, by, bx + boxW, by + boxH, kBlack);
        int row = 0;
        for (const PlotSeries& s : spec.series) {
            if (s.label.empty()) continue;
            const int y = by + 6 + row * lineH;
            const double midY = y + th / 2.0 - 0.5;
            if (s.lines) cv.segment(bx + 8, midY, bx + 40, midY, s.color, 2.0, 0, s.dashed ? 9.0 : 0.0, 6.0);
            if (s.markers) cv.dot(bx + 24, midY, 3.0, s.color);
            cv.text(bx + 48, y, s.label, kBlack);
            ++row;
        }
    }

    // Title and axis labels.
    if (!spec.title.empty()) cv.text((img.width - Canvas::textWidth(spec.title)) / 2, 14, spec.title, kBlack);
    if (!spec.xLabel.empty())
        cv.text((f.left + f.right - Canvas::textWidth(spec.xLabel)) / 2, f.bottom + 14 + th + 8, spec.xLabel, kBlack);
    if (!spec.yLabel.empty())
        cv.text(16, (f.top + f.bottom + Canvas::textWidth(spec.yLabel)) / 2, spec.yLabel, kBlack, true);

    img.pixels = cv.take();
    return img;
}

bool writePlot(const std::string& path, const PlotSpec& spec, std::string& error) {
    const PlotImage img = drawPlot(spec);
    return writeImage(path, img.width, img.height, img.pixels, error);
}

}  // namespace trazo
