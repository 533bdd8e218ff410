// trazo merge: mergePartialFiles, then the image, the partial and the stats; the error estimate on stderr.
#include "merge_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <new>

#include "image/image_writer.h"
#include "io/text_file.h"
#include "render/error_estimate.h"
#include "render/merge.h"
#include "render/progressive_render.h"
#include "render/resolve.h"
#include "render_stats.h"

namespace trazo {

namespace {

void printLines(const std::string& text) {
    size_t at = 0;
    while (at < text.size()) {
        size_t eol = text.find('\n', at);
        if (eol == std::string::npos) eol = text.size();
        std::fprintf(stderr, "trazo: merge: %s\n", text.substr(at, eol - at).c_str());
        at = eol + 1;
    }
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct MergeTimes {
    double merge = 0, write = 0;  // reading and adding the parts; writing the image and the partial
};

std::string formatMergeJson(const MergeResult& r, double relError, bool balanced, const MergeTimes& times) {
    const PartialHeader& h = r.header;
    const Fingerprint& f = h.fingerprint;
    JsonObject j;
    j.add("scene", jsonString(f.scenePath));
    j.add("parts", std::to_string(h.parts));
    j.add("spp", std::to_string(passCount(h.passes)));
    j.add("passes", jsonString(formatRanges(h.passes)));
    j.add("missing", jsonString(formatRanges(r.missing)));
    j.add("render_s", jsonNumber(h.seconds));
    j.add("merge_s", jsonNumber(times.merge));
    j.add("write_s", jsonNumber(times.write));
    j.add("rays", std::to_string(h.rays));
    j.add("mrays_per_s", jsonNumber(h.seconds > 0 ? h.rays / h.seconds * 1e-6 : 0.0));
    j.add("backend", jsonString(h.backend));
    j.add("width", std::to_string(f.width));
    j.add("height", std::to_string(f.height));
    j.add("seed", std::to_string(f.seed));
    j.add("blocks", jsonString(f.blocks));
    j.add("full_cycle_spp", std::to_string(f.fullCycle));
    j.add("estimated_rel_error", jsonNumber(relError));
    j.add("estimate_balanced", balanced ? "true" : "false");
    return j.text();
}

}  // namespace

int runMerge(const MergeCommandLine& options) {
    ImageFormat format;
    if (!options.output.empty() && !imageFormatFromPath(options.output, format)) {
        std::fprintf(stderr, "trazo: merge: %s\n", unknownImageFormatReason(options.output).c_str());
        return 2;
    }
    MergeResult result;
    MergeOptions mergeOptions;
    mergeOptions.allowGaps = options.allowGaps;
    mergeOptions.expected = options.passes;
    std::string error;
    MergeTimes times;
    auto t0 = std::chrono::steady_clock::now();
    try {
        if (!mergePartialFiles(options.parts, mergeOptions, result, error)) {
            printLines(error);
            std::fputs("trazo: merge: nothing was written\n", stderr);
            return 2;
        }
    } catch (const std::bad_alloc&) {
        std::fputs("trazo: merge: out of memory (std::bad_alloc); nothing was written\n", stderr);
        return 1;
    }
    times.merge = secondsSince(t0);
    const PartialHeader& h = result.header;
    const Fingerprint& f = h.fingerprint;
    const uint32_t passes = passCount(h.passes);
    for (const PassRange& r : result.missing)
        std::fprintf(stderr, "trazo: merge: passes %s are missing; merging the %u passes there are (%s)\n",
                     formatRange(r).c_str(), passes, formatRanges(h.passes).c_str());

    const ErrorEstimate estimate = estimateError(result.accum);
    // Unbiased where the halves hold equal strata: one range of whole windows from pass 0 (error_tracker.h).
    const bool balanced = estimate.available && h.passes.size() == 1 && h.passes[0].first == 0 &&
                          halvesBalanced(f.fullCycle, h.passes[0]);

    t0 = std::chrono::steady_clock::now();
    if (!options.partialPath.empty() && !writePartialFile(options.partialPath, h, result.accum, error)) {
        std::fprintf(stderr, "trazo: merge: %s\n", error.c_str());
        return 1;
    }
    if (!options.output.empty()) {
        const std::vector<Vec3> image = resolveImage(result.accum);
        // The scene's Exposure and view transform, as the parts recorded them (SPEC §7 Image).
        const DisplayTransform display{std::exp2(f.exposure), f.srgb};
        if (!writeImage(options.output, (int)f.width, (int)f.height, image, error, display)) {
            std::fprintf(stderr, "trazo: merge: %s\n", error.c_str());
            return 1;
        }
    }
    times.write = secondsSince(t0);
    if (!options.statsPath.empty() &&
        !writeTextFileAtomically(options.statsPath, formatMergeJson(result, estimate.relError, balanced, times),
                                 error)) {
        std::fprintf(stderr, "trazo: merge: %s\n", error.c_str());
        return 1;
    }
    if (!options.quiet) {
        std::fprintf(stderr, "trazo: merge: %u parts, passes %s (%u), %llu rays, %.4f s of rendering; %ux%u\n", h.parts,
                     formatRanges(h.passes).c_str(), passes, (unsigned long long)h.rays, h.seconds, f.width, f.height);
    }
    if (estimate.available)
        std::fprintf(stderr, "trazo: merge: estimated relative error %.3g%%%s\n", 100.0 * estimate.relError,
                     balanced ? "" : " (rough: passes not whole windows of 2 cycles from 0)");
    else
        std::fputs("trazo: merge: estimated relative error: n/a (needs 2 or more passes)\n", stderr);
    return 0;
}

}  // namespace trazo
