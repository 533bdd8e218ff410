// The headless render: the seed's three timed phases (scene creation, upload, render), then the file.
#include "headless_render.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include <sys/resource.h>

#include "device/flatten.h"
#include "image/image_writer.h"
#include "io/text_file.h"
#include "progress_bar.h"
#include "render/error_estimate.h"
#include "render/frame_setup.h"
#include "render/progressive_render.h"
#include "render_stats.h"
#include "scene/scene_reader.h"

namespace trazo {

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The process's peak resident set so far, in MB (Linux reports ru_maxrss in KiB).
double peakRssMegabytes() {
    struct rusage usage {};
    if (getrusage(RUSAGE_SELF, &usage) != 0) return 0.0;
    return (double)usage.ru_maxrss / 1024.0;
}

}  // namespace

int runHeadlessRender(const CommandLine& options) {
    ImageFormat format;
    if (!imageFormatFromPath(options.output, format)) {
        std::fprintf(stderr, "trazo: %s\n", unknownImageFormatReason(options.output).c_str());
        return 2;
    }

    RenderStats stats;
    stats.scene = options.renderScene;
    stats.seed = options.seed;

    auto t0 = std::chrono::steady_clock::now();
    Diagnostics diags;
    const Scene scene = readSceneFile(options.renderScene, diags);
    printDiagnostics(diags);
    if (diags.hasErrors()) return 2;
    stats.readSeconds = secondsSince(t0);
    const auto buildStart = std::chrono::steady_clock::now();
    FlattenResult flat = flatten(scene);
    stats.buildSeconds = secondsSince(buildStart);
    if (!flat.unsupported.empty()) {
        std::string list;
        for (const std::string& s : flat.unsupported) list += (list.empty() ? "" : "; ") + s;
        std::fprintf(stderr, "%s: warning: rendering without what this version cannot draw yet: %s\n",
                     options.renderScene.c_str(), list.c_str());
    }
    stats.width = options.width.value_or((uint32_t)scene.settings.renderWidth);
    stats.height = options.height.value_or((uint32_t)scene.settings.renderHeight);
    const StrataBlocks blocks = options.blocks.value_or(headlessBlocks(flat.arrays));
    stats.fullCycle = fullCyclePasses(flat.arrays, blocks);
    stats.blocks = describeBlocks(blocks);
    stats.features = describeFeatures(flat.arrays.features);
    stats.parseSeconds = secondsSince(t0);

    try {
        std::string why;
        std::unique_ptr<Backend> backend = createBackendFor(flat.arrays, options.backend, options.threads, why);
        if (!backend) {
            std::fprintf(stderr, "trazo: cannot use the CUDA backend: %s\n", why.c_str());
            return 1;
        }
        stats.backend = backend->name();
        stats.device = backend->deviceName();
        if (!options.quiet || options.backend == BackendChoice::Auto) {
            std::fprintf(stderr, "trazo: rendering on %s (%s)%s%s\n", stats.backend.c_str(), stats.device.c_str(),
                         why.empty() ? "" : "; CUDA not used: ", why.c_str());
        }

        // What is needed of the arrays below is taken first: the backend may keep them instead of a copy.
        const uint32_t cameraPasses = cameraPathPasses(flat.arrays, blocks);
        t0 = std::chrono::steady_clock::now();
        backend->uploadMoved(std::move(flat.arrays));
        backend->resize(stats.width, stats.height);
        stats.uploadSeconds = secondsSince(t0);

        const FrameParams frame =
            makeFrameParams(scene, stats.width, stats.height, options.seed, blocks);
        RenderLimits limits;
        limits.seconds = options.seconds;
        limits.targetError = options.targetError;
        limits.cyclePasses = stats.fullCycle;
        if (options.targetError > 0 && !splitsHalves(limits.cyclePasses)) {
            std::fprintf(stderr, "trazo: --target-error: this scene's strata do not repeat within %u passes, so "
                                 "its error cannot be estimated; use --spp or --time\n", kMaxCyclePasses);
            return 2;
        }
        // Default: one complete estimate (every stratum of every grid on the camera path once:
        // cameraPathPasses); bounded only by the time or the target error when either is given.
        const bool openEnded = options.seconds > 0 || options.targetError > 0;
        limits.passes = options.spp ? *options.spp
                                    : (openEnded ? kMaxProgressivePasses : cameraPasses);
        ProgressBar bar(!options.quiet, options.seconds);
        const RenderOutcome outcome =
            renderProgressive(*backend, frame, limits, [&](const RenderProgress& p) { bar.update(p); });
        bar.finish();
        stats.spp = outcome.passes;
        stats.renderSeconds = outcome.seconds;
        stats.rays = outcome.rays;
        stats.fixedGrid = options.fixedGrid;
        stats.targetError = options.targetError;
        stats.reachedTarget = outcome.reachedTarget;

        std::vector<AccumPixel> accum;
        backend->readAccumulation(accum);
        const ErrorEstimate estimate = estimateError(accum);
        stats.estimatedRelError = estimate.relError;
        stats.estimateBalanced =
            estimate.available && splitsHalves(limits.cyclePasses) && outcome.passes % (2 * limits.cyclePasses) == 0;

        std::string error;
        if (!writeImage(options.output, (int)stats.width, (int)stats.height, resolveImage(accum), error)) {
            std::fprintf(stderr, "trazo: %s\n", error.c_str());
            return 1;
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "trazo: %s\n", e.what());
        return 1;
    }

    stats.peakRssMb = peakRssMegabytes();
    if (!options.quiet) std::fputs(formatStatsSummary(stats).c_str(), stderr);
    if (!options.statsPath.empty()) {
        std::string error;
        if (!writeTextFileAtomically(options.statsPath, formatStatsJson(stats), error)) {
            std::fprintf(stderr, "trazo: %s\n", error.c_str());
            return 1;
        }
    }
    return 0;
}

}  // namespace trazo
