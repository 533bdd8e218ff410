// convergence_bench: for one scene, a high-pass reference (another seed), then one render read at 1, 2, 4, …
// passes (and at whole cycles), with time, RMSE, relative error and relative MSE against the reference and the
// render's own error estimate, for one stratum per pass and for the headless default's blocks (the same time);
// optionally the fixed-grid estimator too. Writes DIR/NAME.csv and DIR/NAME.png
// (log–log error against time, with a 1/√t line), prints the table and the time to reach 5%, 2% and 1%.
//   convergence_bench SCENE [--reference-passes R] [--max-passes M] [--threads N] [--fixed-grid-too]
//                           [--out-dir DIR] [--width W] [--height H] [--seed S] [--backend cpu|cuda]
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "flatten/flatten.h"
#include "scene/scene_reader.h"
#include "support/convergence_series.h"
#include "support/plot.h"

namespace {

using namespace trazo;
using namespace trazo::convergence;

struct Options {
    std::string scene;
    uint32_t referencePasses = 0;  // 0: 16 cycles, at least 1024 passes
    uint32_t maxPasses = 1024;
    unsigned threads = 0;
    bool fixedGridToo = false;
    std::string outDir = "convergence_out";
    uint32_t width = 0, height = 0, seed = 1;
    BackendChoice backend = BackendChoice::Auto;
};

int usage() {
    std::fprintf(stderr,
                 "usage: convergence_bench SCENE [--reference-passes R] [--max-passes M] [--threads N]\n"
                 "                         [--fixed-grid-too] [--out-dir DIR] [--width W] [--height H] [--seed S]\n"
                 "                         [--backend auto|cpu|cuda]\n");
    return 2;
}

bool parse(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
        const char* v = nullptr;
        if (a == "--fixed-grid-too") o.fixedGridToo = true;
        else if (a == "--reference-passes" && (v = value())) o.referencePasses = std::stoul(v);
        else if (a == "--max-passes" && (v = value())) o.maxPasses = std::max(1ul, std::stoul(v));
        else if (a == "--threads" && (v = value())) o.threads = std::stoul(v);
        else if (a == "--out-dir" && (v = value())) o.outDir = v;
        else if (a == "--width" && (v = value())) o.width = std::stoul(v);
        else if (a == "--height" && (v = value())) o.height = std::stoul(v);
        else if (a == "--seed" && (v = value())) o.seed = std::stoul(v);
        else if (a == "--backend" && (v = value())) {
            const std::string b = v;
            o.backend = b == "cpu" ? BackendChoice::Cpu : (b == "cuda" ? BackendChoice::Cuda : BackendChoice::Auto);
        } else if (!a.empty() && a[0] != '-' && o.scene.empty()) o.scene = a;
        else return false;
    }
    return !o.scene.empty();
}

std::string percent(double v) {
    char buf[32];
    if (!std::isfinite(v)) return "n/a";
    std::snprintf(buf, sizeof buf, "%.3f%%", 100.0 * v);
    return buf;
}

void printTable(const char* name, const std::vector<ConvergencePoint>& points) {
    for (const ConvergencePoint& p : points)
        std::printf("| %s | %u | %.4f | %.5g | %s | %s | %.4g | %s | %s |\n", name, p.passes, p.seconds, p.rmse,
                    percent(p.trueRelError).c_str(), percent(p.relError).c_str(), p.relMse,
                    percent(p.estRelError).c_str(),
                    p.balanced ? "balanced" : (p.wholeCycles ? "whole cycles" : ""));
}

void writeCsvRows(std::ofstream& csv, const char* name, const std::vector<ConvergencePoint>& points) {
    for (const ConvergencePoint& p : points) {
        char buf[256];
        std::snprintf(buf, sizeof buf, "%s,%u,%.6f,%.6g,%.6g,%.6g,%.6g,%.6g,%d,%d\n", name, p.passes, p.seconds,
                      p.rmse, p.relError, p.relMse, p.trueRelError, p.estRelError, p.balanced ? 1 : 0,
                      p.wholeCycles ? 1 : 0);
        csv << buf;
    }
}

PlotSeries series(const std::vector<ConvergencePoint>& points, const std::string& label, Vec3 color,
                  bool (*keep)(const ConvergencePoint&), bool estimate = false) {
    PlotSeries s;
    s.label = label;
    s.color = color;
    for (const ConvergencePoint& p : points) {
        if (keep && !keep(p)) continue;
        s.x.push_back(p.seconds);
        s.y.push_back(estimate ? p.estRelError : p.trueRelError);
    }
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parse(argc, argv, o)) return usage();

    Diagnostics diags;
    const Scene scene = readSceneFile(o.scene, diags);
    printDiagnostics(diags);
    if (diags.hasErrors()) return 2;
    const FlattenResult flat = flatten(scene);
    const uint32_t width = o.width ? o.width : (uint32_t)scene.settings.renderWidth;
    const uint32_t height = o.height ? o.height : (uint32_t)scene.settings.renderHeight;
    const uint32_t cycle = fullCyclePasses(flat.arrays, StrataBlocks::ones());
    if (!o.referencePasses) o.referencePasses = std::max(16 * cycle, 1024u);

    std::string why;
    auto backend = createBackend(o.backend, o.threads, why);
    if (!backend) {
        std::fprintf(stderr, "convergence_bench: %s\n", why.c_str());
        return 1;
    }
    const std::string name = std::filesystem::path(o.scene).stem().string();
    std::printf("# %s: %ux%u, full cycle %u passes, %s (%s)\n", o.scene.c_str(), width, height, cycle,
                backend->name().c_str(), backend->deviceName().c_str());
    std::fflush(stdout);

    const Reference ref = renderReference(*backend, scene, flat.arrays, width, height, o.referencePasses, o.seed + 1000);
    std::printf("# reference: %u passes, seed %u, %.2f s, its own estimated relative error %s (removed in "
                "quadrature from the measured error: \"rel. error\" below)\n",
                ref.passes, o.seed + 1000, ref.seconds, percent(ref.estRelError).c_str());
    std::fflush(stdout);

    SeriesRequest req;
    req.width = width, req.height = height, req.seed = o.seed, req.maxPasses = o.maxPasses;
    const std::vector<ConvergencePoint> progressive = runSeries(*backend, scene, flat.arrays, ref, req);
    // The headless default's blocks (whole camera-path grids where nothing cycles above them), same time budget.
    req.blocks = headlessBlocks(flat.arrays);
    req.maxSeconds = progressive.empty() ? 0 : progressive.back().seconds;
    const std::vector<ConvergencePoint> blocked = runSeries(*backend, scene, flat.arrays, ref, req);
    std::vector<ConvergencePoint> fixedGrid;
    if (o.fixedGridToo) {
        req.blocks = StrataBlocks::whole();
        req.maxSeconds = progressive.empty() ? 0 : progressive.back().seconds;  // about the same time budget
        fixedGrid = runSeries(*backend, scene, flat.arrays, ref, req);
    }

    std::printf("| estimator | passes | render s | RMSE | rel. error | raw rel. error | rel. MSE | estimated rel. error | halves |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    printTable("progressive", progressive);
    printTable("default-blocks", blocked);
    if (o.fixedGridToo) printTable("fixed-grid", fixedGrid);

    std::error_code ec;
    std::filesystem::create_directories(o.outDir, ec);
    const std::string csvPath = o.outDir + "/" + name + ".csv", pngPath = o.outDir + "/" + name + ".png";
    {
        std::ofstream csv(csvPath);
        csv << "estimator,passes,seconds,rmse,raw_rel_error,rel_mse,rel_error,est_rel_error,halves_balanced,"
               "whole_cycles\n";
        writeCsvRows(csv, "progressive", progressive);
        writeCsvRows(csv, "default-blocks", blocked);
        writeCsvRows(csv, "fixed-grid", fixedGrid);
        if (!csv) std::fprintf(stderr, "convergence_bench: cannot write %s\n", csvPath.c_str());
    }

    PlotSpec plot;
    plot.title = name + ": relative error vs render time (" + std::to_string(width) + "x" +
                 std::to_string(height) + ", " + backend->name() + ")";
    plot.xLabel = "render time (s)";
    plot.yLabel = "relative error";
    plot.series.push_back(series(progressive, "progressive", Vec3(0.12f, 0.35f, 0.80f), nullptr));
    if (cycle > 1) {
        PlotSeries whole = series(progressive, "progressive at whole cycles", Vec3(0.95f, 0.55f, 0.05f),
                                  [](const ConvergencePoint& p) { return p.wholeCycles; });
        whole.lines = false;
        plot.series.push_back(whole);
    }
    PlotSeries est = series(progressive, "progressive, self-estimate", Vec3(0.55f, 0.70f, 0.95f),
                            [](const ConvergencePoint& p) { return p.passes > 1; }, true);
    est.dashed = true;
    plot.series.push_back(est);
    plot.series.push_back(series(blocked, "default blocks (" + describeBlocks(req.blocks) + ")",
                                 Vec3(0.10f, 0.60f, 0.25f), nullptr));
    if (o.fixedGridToo) plot.series.push_back(series(fixedGrid, "fixed grid", Vec3(0.85f, 0.10f, 0.10f), nullptr));
    // 1/√t through the last progressive point, across the whole time range.
    if (!progressive.empty()) {
        double tMin = progressive.front().seconds, tMax = progressive.back().seconds;
        for (const ConvergencePoint& p : fixedGrid) tMin = std::min(tMin, p.seconds), tMax = std::max(tMax, p.seconds);
        const ConvergencePoint& last = progressive.back();
        PlotSeries slope;
        slope.label = "1/sqrt(t)";
        slope.dashed = true;
        slope.markers = false;
        for (double t : {tMin, tMax}) {
            slope.x.push_back(t);
            slope.y.push_back(last.trueRelError * std::sqrt(last.seconds / t));
        }
        plot.series.push_back(slope);
    }
    std::string error;
    if (!writePlot(pngPath, plot, error)) std::fprintf(stderr, "convergence_bench: %s\n", error.c_str());

    std::printf("\nlog-log slope of rel. error vs time (points past one cycle): progressive %.3f",
                logLogSlope(progressive, cycle));
    if (o.fixedGridToo) std::printf(", fixed grid %.3f", logLogSlope(fixedGrid, 1));
    std::printf("\n");
    for (double x : {0.05, 0.02, 0.01}) {
        std::printf("time to reach %g%% relative error:", 100 * x);
        auto show = [&](const char* label, const std::vector<ConvergencePoint>& pts) {
            const double t = timeToReach(pts, x);
            if (!pts.empty() && pts.front().trueRelError <= x) std::printf("  %s <= %.4f s (first read)", label, t);
            else if (std::isfinite(t)) std::printf("  %s %.4f s", label, t);
            else std::printf("  %s not reached", label);
        };
        show("progressive", progressive);
        show("default-blocks", blocked);
        if (o.fixedGridToo) show("fixed-grid", fixedGrid);
        std::printf("\n");
    }
    // The thesis's quality: the error of one fixed-grid pass, which is exactly the thesis's estimator.
    if (o.fixedGridToo && !fixedGrid.empty()) {
        const ConvergencePoint& thesis = fixedGrid.front();
        const double t = timeToReach(progressive, thesis.trueRelError);
        std::printf("thesis quality (one fixed-grid pass): rel. error %.3f%% in %.4f s; progressive reaches it in ",
                    100 * thesis.trueRelError, thesis.seconds);
        if (std::isfinite(t)) std::printf("%.4f s (%.2fx)\n", t, thesis.seconds / t);
        else std::printf("more than %.4f s\n", progressive.empty() ? 0.0 : progressive.back().seconds);
    }
    std::printf("wrote %s and %s\n", csvPath.c_str(), pngPath.c_str());
    return 0;
}
