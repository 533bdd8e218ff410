// partial_merge_bench: what partial files cost (bytes, write and read seconds at 4K) and how `trazo merge`'s
// time grows with the number of parts (--plot: also as a picture). Synthetic accumulations (every pixel's
// counts equal, as a headless render's are), written to and read from --dir (the page cache, unless the files
// outgrow memory).
//   partial_merge_bench [--dir DIR] [--width 256 --height 256] [--parts 1,4,16,64,256] [--skip-4k]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "render/merge.h"
#include "render/partial_file.h"
#include "support/plot.h"

namespace {

using namespace trazo;
namespace fs = std::filesystem;

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

PartialHeader headerFor(uint32_t width, uint32_t height, PassRange range) {
    PartialHeader h;
    h.fingerprint.scenePath = "bench.scene";
    h.fingerprint.width = width;
    h.fingerprint.height = height;
    h.fingerprint.blocks = "1,100,1,5";
    h.fingerprint.fullCycle = 100;
    h.fingerprint.version = "trazo bench";
    h.passes = {range};
    h.requested = range;
    h.backend = "bench";
    return h;
}

std::vector<AccumPixel> accumFor(uint32_t width, uint32_t height, PassRange range) {
    std::vector<AccumPixel> accum((size_t)width * height);
    const double n = range.count();
    for (size_t i = 0; i < accum.size(); ++i) {
        const double v = n * (0.25 + 1e-7 * (double)(i % 1000003) + 1e-3 * range.first);
        accum[i] = AccumPixel{{v, 0.5 * v, 0.25 * v}, n, {0.5 * v, 0.25 * v, 0.125 * v}, n / 2};
    }
    return accum;
}

bool fail(const std::string& error) {
    std::fprintf(stderr, "partial_merge_bench: %s\n", error.c_str());
    return false;
}

bool bench4k(const std::string& dir) {
    const uint32_t w = 3840, h = 2160;
    const std::vector<AccumPixel> accum = accumFor(w, h, {0, 64});
    const std::string path = dir + "/4k.part";
    std::string error;
    double write = 1e30, header = 1e30, read = 1e30;
    std::vector<AccumPixel> back;  // reused, as a merge reuses its part buffer
    for (int rep = 0; rep < 3; ++rep) {
        auto t0 = std::chrono::steady_clock::now();
        if (!writePartialFile(path, headerFor(w, h, {0, 64}), accum, error)) return fail(error);
        const double thisWrite = secondsSince(t0);
        write = std::min(write, thisWrite);
        PartialHeader hd;
        t0 = std::chrono::steady_clock::now();
        if (!readPartialHeader(path, hd, error)) return fail(error);
        header = std::min(header, secondsSince(t0));
        t0 = std::chrono::steady_clock::now();
        if (!readPartialFile(path, hd, back, error)) return fail(error);
        read = std::min(read, secondsSince(t0));
        // The first read allocates the buffer: its first touch is part of what a fresh merge process pays.
        std::printf("  4K rep %d: write %.3f s, read + checksum %.3f s%s\n", rep, thisWrite, secondsSince(t0),
                    rep == 0 ? " (into a freshly allocated buffer)" : "");
    }
    const uintmax_t bytes = fs::file_size(path);
    std::printf("4K partial (3840x2160, uniform counts): %ju bytes (%.1f MiB, %.2f bytes a pixel); write %.3f s, "
                "read header %.6f s, read + checksum %.3f s (best of 3: a resident buffer)\n",
                bytes, (double)bytes / (1 << 20), (double)bytes / ((double)w * h), write, header, read);
    fs::remove(path);
    return true;
}

// Merge seconds against parts on log-log axes, with the line through the first point at one part's cost per
// part (linear growth), so a departure from linear shows.
bool plotMerge(const std::string& path, uint32_t w, uint32_t h, const std::vector<double>& parts,
               const std::vector<double>& seconds) {
    PlotSpec plot;
    plot.title = "trazo merge: seconds against parts (" + std::to_string(w) + "x" + std::to_string(h) + " each)";
    plot.xLabel = "parts";
    plot.yLabel = "merge seconds";
    PlotSeries measured{"measured (best of 2)", parts, seconds, Vec3(0.12f, 0.35f, 0.80f)};
    PlotSeries linear{"linear from 1 part", parts, {}, Vec3(0.5f), true, false};
    for (double p : parts) linear.y.push_back(seconds[0] / parts[0] * p);
    plot.series = {measured, linear};
    std::string error;
    if (!writePlot(path, plot, error)) return fail(error);
    std::printf("plot: %s\n", path.c_str());
    return true;
}

bool benchMerge(const std::string& dir, uint32_t w, uint32_t h, const std::vector<int>& counts,
                const std::string& plotPath) {
    std::vector<double> partsDone, secondsTaken;
    std::printf("merge of P parts of %ux%u (%.2f MiB each):\n  parts  seconds  seconds/part  MB/s\n", w, h,
                (double)(16 + (uint64_t)w * h * 48 + 512) / (1 << 20));
    int written = 0;
    std::vector<std::string> paths;
    std::string error;
    for (int parts : counts) {
        for (; written < parts; ++written) {
            const PassRange range{(uint32_t)written, (uint32_t)written + 1};
            paths.push_back(dir + "/part" + std::to_string(written) + ".part");
            if (!writePartialFile(paths.back(), headerFor(w, h, range), accumFor(w, h, range), error))
                return fail(error);
        }
        const std::vector<std::string> some(paths.begin(), paths.begin() + parts);
        double best = 1e30;
        for (int rep = 0; rep < 2; ++rep) {
            MergeResult result;
            const auto t0 = std::chrono::steady_clock::now();
            if (!mergePartialFiles(some, {}, result, error)) return fail(error);
            best = std::min(best, secondsSince(t0));
        }
        double bytes = 0;
        for (const std::string& p : some) bytes += (double)fs::file_size(p);
        std::printf("  %5d  %7.3f  %12.5f  %5.0f\n", parts, best, best / parts, bytes / best * 1e-6);
        partsDone.push_back(parts);
        secondsTaken.push_back(best);
    }
    for (const std::string& p : paths) fs::remove(p);
    return plotPath.empty() || plotMerge(plotPath, w, h, partsDone, secondsTaken);
}

}  // namespace

int main(int argc, char** argv) {
    std::string dir = fs::temp_directory_path().string();
    uint32_t width = 256, height = 256;
    std::vector<int> counts{1, 4, 16, 64, 256};
    bool skip4k = false;
    std::string plotPath;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&] { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
        if (a == "--dir") dir = next();
        else if (a == "--width") width = (uint32_t)std::atoi(next().c_str());
        else if (a == "--height") height = (uint32_t)std::atoi(next().c_str());
        else if (a == "--skip-4k") skip4k = true;
        else if (a == "--plot") plotPath = next();
        else if (a == "--parts") {
            counts.clear();
            const std::string list = next();
            for (size_t at = 0; at < list.size();) {
                size_t comma = list.find(',', at);
                if (comma == std::string::npos) comma = list.size();
                counts.push_back(std::atoi(list.substr(at, comma - at).c_str()));
                at = comma + 1;
            }
        } else {
            std::fprintf(stderr, "usage: partial_merge_bench [--dir DIR] [--width W --height H] [--parts 1,4,16] "
                                 "[--skip-4k] [--plot FILE.png]\n");
            return 2;
        }
    }
    dir += "/trazo_partial_bench";
    fs::create_directories(dir);
    const bool ok = (skip4k || bench4k(dir)) && benchMerge(dir, width, height, counts, plotPath);
    fs::remove_all(dir);
    return ok ? 0 : 1;
}
