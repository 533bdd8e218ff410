// The headless render: the seed's three timed phases (scene creation, upload, render), then the file.
#include "headless_render.h"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <new>
#include <stdexcept>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

#include "flatten/flatten.h"
#include "image/image_writer.h"
#include "io/text_file.h"
#include "progress_bar.h"
#include "render/error_estimate.h"
#include "render/frame_setup.h"
#include "render/multi_backend.h"
#include "render/partial_file.h"
#include "render/progressive_render.h"
#include "render/render_plan.h"
#include "render/render_start.h"
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

std::string formatBytes(uint64_t bytes) {
    char text[64];
    std::snprintf(text, sizeof text, "%llu bytes (%.1f GiB)", (unsigned long long)bytes,
                  (double)bytes / (1024.0 * 1024.0 * 1024.0));
    return text;
}

// Says why the image's memory is refused; false.
bool refuseMemory(const RenderPlan& plan, const char* why) {
    std::fprintf(stderr, "trazo: a %u×%u render needs %s of memory for its accumulation and image (%u bytes a "
                         "pixel)%s; use a smaller --width/--height\n",
                 plan.width, plan.height, formatBytes(plan.hostBytes).c_str(), (unsigned)kHostBytesPerPixel, why);
    return false;
}

int renderScene(const CommandLine& options, const Scene& scene, RenderStats& stats,
                std::chrono::steady_clock::time_point t0);

// SIGTERM (what Slurm sends at a task's time limit) or SIGINT during a partial render: finish the batch, write
// the partial of the passes done. The handler then goes back to the default, so a second signal ends it at once.
std::atomic<bool> stopRequested{false};
volatile std::sig_atomic_t stopSignal = 0;
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

void requestStop(int signal) {
    stopSignal = signal;
    stopRequested.store(true);
}

void stopOnSignals() {
    struct sigaction action {};
    action.sa_handler = requestStop;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    sigaction(SIGTERM, &action, nullptr);
    sigaction(SIGINT, &action, nullptr);
}

// --devices: one CUDA backend per listed device, as a MultiBackend when there are several; with one device
// exactly the backend `--backend cuda` opens on it. Null after saying why.
std::unique_ptr<Backend> openDevices(const CommandLine::DeviceList& devices, const SceneArrays& arrays) {
    std::string why;
    const int count = cudaDeviceCount(why);
    if (count == 0) {
        std::fprintf(stderr, "trazo: --devices: cannot use the CUDA backend: %s\n", why.c_str());
        return nullptr;
    }
    std::vector<int> ids = devices.ids;
    if (devices.all)
        for (int i = 0; i < count; ++i) ids.push_back(i);
    std::vector<std::unique_ptr<Backend>> backends;
    for (int id : ids) {
        if (id >= count) {
            std::fprintf(stderr, "trazo: --devices: there is no CUDA device %d (this machine has %d: 0 to %d)\n", id,
                         count, count - 1);
            return nullptr;
        }
        std::unique_ptr<Backend> backend = createCudaBackendOn(id, why);
        if (backend && !backend->accepts(arrays, why)) backend.reset();
        if (!backend) {
            std::fprintf(stderr, "trazo: --devices: cannot use CUDA device %d: %s\n", id, why.c_str());
            return nullptr;
        }
        backends.push_back(std::move(backend));
    }
    if (backends.size() == 1) return std::move(backends[0]);
    return std::make_unique<MultiBackend>(std::move(backends));
}

}  // namespace

int runHeadlessRender(const CommandLine& options) {
    ImageFormat format;
    if (options.partialPath.empty() && !imageFormatFromPath(options.output, format)) {
        std::fprintf(stderr, "trazo: %s\n", unknownImageFormatReason(options.output).c_str());
        return 2;
    }

    RenderStats stats;
    stats.scene = options.renderScene;
    stats.seed = options.seed;

    // Everything from reading on runs inside the handler: memory exhausted anywhere (a reader's buffers, the
    // flattened arrays, the backend) is a message and status 1, never an abort, and no image is written.
    try {
        const auto t0 = std::chrono::steady_clock::now();
        Diagnostics diags;
        const Scene scene = readSceneFile(options.renderScene, diags);
        if (!diags.hasErrors()) checkRenderBounds(scene, diags);
        printDiagnostics(diags);
        if (diags.hasErrors()) return 2;
        return renderScene(options, scene, stats, t0);
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "trazo: %s: out of memory (std::bad_alloc); nothing was written\n",
                     options.renderScene.c_str());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "trazo: %s\n", e.what());
        return 1;
    }
}

namespace {

// --devices, or --backend and --threads; says which it opened. Null after saying why not.
std::unique_ptr<Backend> openRenderBackend(const CommandLine& options, const SceneArrays& arrays, RenderStats& stats) {
    std::string fallback;
    std::unique_ptr<Backend> backend = options.devices ? openDevices(*options.devices, arrays)
                                                       : openBackend(options.backend, options.threads, &arrays, fallback);
    if (!backend) return nullptr;
    stats.backend = backend->name();
    stats.device = backend->deviceName();
    if (!options.quiet || options.backend == BackendChoice::Auto)
        std::fprintf(stderr, "trazo: rendering on %s\n", describeBackend(*backend, fallback).c_str());
    return backend;
}

// What the render did and the error it reached, for the summary and --stats.
void recordOutcome(RenderStats& stats, const CommandLine& options, const RenderOutcome& outcome,
                   const ErrorEstimate& estimate, bool halvesBalanced) {
    stats.spp = outcome.passes;
    stats.renderSeconds = outcome.seconds;
    stats.rays = outcome.rays;
    stats.fixedGrid = options.fixedGrid;
    stats.targetError = options.request.targetError;
    stats.reachedTarget = outcome.reachedTarget;
    stats.estimatedRelError = estimate.relError;
    stats.probePixels = estimate.probePixels;
    stats.estimateBalanced = estimate.available && (estimate.exact || estimate.probePixels > 0 || halvesBalanced);
    stats.noSamplingNoise = estimate.exact;
}

// The image's memory, sized up front: refused here, before any pass, rather than after the render. Reserves
// the accumulation read back and (but for a partial) the image. False after saying why.
bool reserveImageMemory(const RenderPlan& plan, bool partial, std::vector<AccumPixel>& accum, std::vector<Vec3>& image) {
    const uint64_t physical = (uint64_t)sysconf(_SC_PHYS_PAGES) * (uint64_t)sysconf(_SC_PAGESIZE);
    if (physical > 0 && plan.hostBytes > physical) return refuseMemory(plan, ", more than this machine has");
    try {
        accum.reserve(plan.pixels());
        if (!partial) image.reserve(plan.pixels());
    } catch (const std::bad_alloc&) {
        return refuseMemory(plan, ", which cannot be allocated");
    }
    return true;
}

// The image, resolved into the capacity reserved for it and stored through the scene's Exposure and
// ViewTransform (SPEC §7 Image). The backend's accumulation goes first: room for the writer's buffer.
bool writeImageFile(const std::string& path, const DisplayTransform& display, const RenderPlan& plan,
                    std::unique_ptr<Backend>& backend, std::vector<AccumPixel>& accum, std::vector<Vec3>& image) {
    backend.reset();
    for (const AccumPixel& p : accum) image.push_back(p.estimate());  // resolveImage, into the reserved image
    std::vector<AccumPixel>().swap(accum);
    std::string error;
    if (writeImage(path, (int)plan.width, (int)plan.height, image, error, display)) return true;
    std::fprintf(stderr, "trazo: %s\n", error.c_str());
    return false;
}

// The partial file of the passes done, and a line when they are fewer than asked for.
bool writePartial(const CommandLine& options, const RenderPlan& plan, const RenderStats& stats,
                  const Fingerprint& fingerprint, PassRange done, bool signalled, std::unique_ptr<Backend>& backend,
                  const std::vector<AccumPixel>& accum) {
    PartialHeader header;
    header.fingerprint = fingerprint;
    header.fingerprint.width = plan.width;
    header.fingerprint.height = plan.height;
    header.fingerprint.seed = options.seed;
    header.fingerprint.blocks = stats.blocks;
    header.fingerprint.fullCycle = plan.fullCycle;
    header.fingerprint.version = "trazo " TRAZO_VERSION;
    header.passes = {done};
    header.requested = plan.openEndedPartial ? done : plan.range;
    header.rays = stats.rays;
    header.seconds = stats.renderSeconds;
    header.backend = describeBackend(*backend, "");
    backend.reset();
    std::string error;
    if (!writePartialFile(options.partialPath, header, accum, error)) {
        std::fprintf(stderr, "trazo: %s\n", error.c_str());
        return false;
    }
    if (plan.openEndedPartial)
        std::fprintf(stderr, "trazo: stopped by --time after passes %s: wrote them to %s\n", formatRange(done).c_str(),
                     options.partialPath.c_str());
    else if (done != header.requested || signalled)
        std::fprintf(stderr, "trazo: %s after passes %s of %s: wrote them to %s\n",
                     signalled ? ("stopped by signal " + std::to_string((int)stopSignal)).c_str() : "stopped by --time",
                     formatRange(done).c_str(), formatRange(plan.range).c_str(), options.partialPath.c_str());
    return true;
}

int renderScene(const CommandLine& options, const Scene& scene, RenderStats& stats,
                std::chrono::steady_clock::time_point t0) {
    stats.readSeconds = secondsSince(t0);
    const auto buildStart = std::chrono::steady_clock::now();
    FlattenResult flat = flatten(scene);
    stats.buildSeconds = secondsSince(buildStart);
    printDiagnostics(flat.warnings);
    const RenderRequest& request = options.request;
    const RenderPlan plan = planRender(request, scene, flat.arrays);
    stats.width = plan.width;
    stats.height = plan.height;
    stats.fullCycle = plan.fullCycle;
    stats.blocks = describeBlocks(plan.blocks);
    stats.features = describeFeatures(flat.arrays.features);
    stats.parseSeconds = secondsSince(t0);

    Fingerprint fingerprint;
    std::string error;
    if (request.partial && !hashSceneFiles(scene, fingerprint, error)) {
        std::fprintf(stderr, "trazo: %s\n", error.c_str());
        return 1;
    }
    const SceneSettings& settings = scene.settings;
    const DisplayTransform display = displayTransform(settings.exposure, settings.viewTransform, settings.integrator);
    fingerprint.exposure = settings.exposure;  // for the merge's image: the accumulation does not hold them
    fingerprint.srgb = display.srgb;
    std::vector<AccumPixel> accum;
    std::vector<Vec3> image;
    if (!reserveImageMemory(plan, request.partial, accum, image)) return 1;

    std::unique_ptr<Backend> backend = openRenderBackend(options, flat.arrays, stats);
    if (!backend) return 1;
    if (!plan.note.empty()) std::fprintf(stderr, "trazo: note: %s\n", plan.note.c_str());

    t0 = std::chrono::steady_clock::now();
    backend->uploadMoved(std::move(flat.arrays));
    try {
        backend->resize(plan.width, plan.height);
    } catch (const std::bad_alloc&) {
        refuseMemory(plan, ", which cannot be allocated");
        return 1;
    }
    stats.uploadSeconds = secondsSince(t0);

    RenderLimits limits = plan.limits(request, backend->hasProbe());
    if (const std::string problem = targetErrorProblem(limits); !problem.empty()) {
        std::fprintf(stderr, "trazo: --target-error: %s\n", problem.c_str());
        return 2;
    }
    if (request.partial) {
        limits.stop = &stopRequested;
        stopOnSignals();
    }
    ProgressBar bar(!options.quiet, request.seconds);
    const FrameParams frame = makeFrameParams(scene, plan.width, plan.height, options.seed, plan.blocks);
    const RenderOutcome outcome =
        renderProgressive(*backend, frame, limits, [&](const RenderProgress& p) { bar.update(p); });
    bar.finish();
    if (outcome.passes == 0) {
        std::fprintf(stderr, "trazo: stopped by signal %d before any pass; nothing was written\n", (int)stopSignal);
        return 3;
    }
    const PassRange done{plan.range.first, plan.range.first + outcome.passes};
    const bool signalled = stopRequested.load() && done.end < plan.range.end;
    const ErrorEstimate estimate = estimateRenderError(*backend, limits, outcome.probe, accum);  // into the reserved capacity
    recordOutcome(stats, options, outcome, estimate, halvesBalanced(limits.cyclePasses, done));

    const auto writeStart = std::chrono::steady_clock::now();
    const bool written = request.partial
                             ? writePartial(options, plan, stats, fingerprint, done, signalled, backend, accum)
                             : writeImageFile(options.output, display, plan, backend, accum, image);
    if (!written) return 1;
    stats.writeSeconds = secondsSince(writeStart);

    stats.peakRssMb = peakRssMegabytes();
    if (!options.quiet) std::fputs(formatStatsSummary(stats).c_str(), stderr);
    if (!options.statsPath.empty() && !writeTextFileAtomically(options.statsPath, formatStatsJson(stats), error)) {
        std::fprintf(stderr, "trazo: %s\n", error.c_str());
        return 1;
    }
    return signalled ? 3 : 0;  // a signal stops partial renders only
}

}  // namespace

}  // namespace trazo
