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

#include "device/flatten.h"
#include "image/image_writer.h"
#include "io/text_file.h"
#include "progress_bar.h"
#include "render/error_estimate.h"
#include "render/frame_setup.h"
#include "render/multi_backend.h"
#include "render/partial_file.h"
#include "render/progressive_render.h"
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

// The host memory a render of width × height holds besides the scene: the backend's accumulation (on the CPU
// backend; the CUDA backend holds it on the device), its copy read back for the image, and the resolved image.
// The writer's own buffer (at most 16 bytes a pixel) comes after the accumulation is freed.
constexpr uint64_t kHostBytesPerPixel = 2 * sizeof(AccumPixel) + sizeof(Vec3);

std::string formatBytes(uint64_t bytes) {
    char text[64];
    std::snprintf(text, sizeof text, "%llu bytes (%.1f GiB)", (unsigned long long)bytes,
                  (double)bytes / (1024.0 * 1024.0 * 1024.0));
    return text;
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

int renderScene(const CommandLine& options, const Scene& scene, RenderStats& stats,
                std::chrono::steady_clock::time_point t0) {
    stats.readSeconds = secondsSince(t0);
    const auto buildStart = std::chrono::steady_clock::now();
    FlattenResult flat = flatten(scene);
    stats.buildSeconds = secondsSince(buildStart);
    printDiagnostics(flat.warnings);
    stats.width = options.width.value_or((uint32_t)scene.settings.renderWidth);
    stats.height = options.height.value_or((uint32_t)scene.settings.renderHeight);
    const StrataBlocks blocks = options.blocks.value_or(headlessBlocks(flat.arrays));
    stats.fullCycle = fullCyclePasses(flat.arrays, blocks);
    stats.blocks = describeBlocks(blocks);
    stats.features = describeFeatures(flat.arrays.features);
    stats.parseSeconds = secondsSince(t0);

    // The image's memory, sized up front: refused here, before any pass, rather than after the render.
    const uint64_t pixels = (uint64_t)stats.width * stats.height;
    const uint64_t hostBytes = pixels * kHostBytesPerPixel;
    const uint64_t physical = (uint64_t)sysconf(_SC_PHYS_PAGES) * (uint64_t)sysconf(_SC_PAGESIZE);
    const bool partial = !options.partialPath.empty();
    Fingerprint fingerprint;
    if (partial) {
        std::string error;
        if (!hashSceneFiles(scene, fingerprint, error)) {
            std::fprintf(stderr, "trazo: %s\n", error.c_str());
            return 1;
        }
    }
    std::vector<AccumPixel> accum;
    std::vector<Vec3> image;
    auto refuseMemory = [&](const char* why) {
        std::fprintf(stderr, "trazo: a %u×%u render needs %s of memory for its accumulation and image (%u bytes a "
                             "pixel)%s; use a smaller --width/--height\n",
                     stats.width, stats.height, formatBytes(hostBytes).c_str(), (unsigned)kHostBytesPerPixel, why);
        return 1;
    };
    if (physical > 0 && hostBytes > physical) return refuseMemory(", more than this machine has");
    try {
        accum.reserve(pixels);
        if (!partial) image.reserve(pixels);
    } catch (const std::bad_alloc&) {
        return refuseMemory(", which cannot be allocated");
    }

    std::string fallback;
    std::unique_ptr<Backend> backend = options.devices
                                           ? openDevices(*options.devices, flat.arrays)
                                           : openBackend(options.backend, options.threads, &flat.arrays, fallback);
    if (!backend) return 1;
    stats.backend = backend->name();
    stats.device = backend->deviceName();
    if (!options.quiet || options.backend == BackendChoice::Auto)
        std::fprintf(stderr, "trazo: rendering on %s\n", describeBackend(*backend, fallback).c_str());

    // What is needed of the arrays below is taken first: the backend may keep them instead of a copy.
    const uint32_t cameraPasses = cameraPathPasses(flat.arrays, blocks);
    // Default: one complete estimate (every stratum of every grid on the camera path once:
    // cameraPathPasses); bounded only by the time or the target error when either is given.
    const bool openEnded = options.seconds > 0 || options.targetError > 0;
    const bool openEndedPartial = !options.spp && !options.passes && openEnded;
    const uint32_t defaultEnd = options.spp ? *options.spp : (openEnded ? kMaxProgressivePasses : cameraPasses);
    const PassRange range = options.passes ? *options.passes : PassRange{0, defaultEnd};
    const uint32_t passes = range.count();
    // A long render says what it will cost before it starts (a time limit bounds it already).
    if (options.seconds <= 0) {
        const std::string note = longRenderNote(flat.arrays, blocks, options.targetError > 0 ? cameraPasses : passes,
                                                !options.spp && !options.passes, stats.width, stats.height);
        if (!note.empty()) std::fprintf(stderr, "trazo: note: %s\n", note.c_str());
    }
    t0 = std::chrono::steady_clock::now();
    backend->uploadMoved(std::move(flat.arrays));
    try {
        backend->resize(stats.width, stats.height);
    } catch (const std::bad_alloc&) {
        return refuseMemory(", which cannot be allocated");
    }
    stats.uploadSeconds = secondsSince(t0);

    const FrameParams frame = makeFrameParams(scene, stats.width, stats.height, options.seed, blocks);
    RenderLimits limits;
    limits.seconds = options.seconds;
    limits.targetError = options.targetError;
    limits.cyclePasses = stats.fullCycle;
    // The error probe, but for a partial render: its parts are merged, and the merge estimates from the halves.
    limits.errorProbe = !partial && backend->hasProbe();
    if (options.targetError > 0 && !limits.errorProbe && !splitsHalves(limits.cyclePasses)) {
        std::fprintf(stderr, "trazo: --target-error: this scene's strata do not repeat within %u passes, so "
                             "its error cannot be estimated; use --spp or --time\n", kMaxCyclePasses);
        return 2;
    }
    limits.passes = passes;
    limits.firstPass = range.first;
    if (partial) {
        limits.stop = &stopRequested;
        stopOnSignals();
    }
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

    const PassRange done{range.first, range.first + outcome.passes};
    const bool signalled = stopRequested.load() && done.end < range.end;
    if (outcome.passes == 0) {
        std::fprintf(stderr, "trazo: stopped by signal %d before any pass; nothing was written\n", (int)stopSignal);
        return 3;
    }
    // Into the capacity reserved above.
    const ErrorEstimate estimate = estimateRenderError(*backend, outcome.probe, accum);
    stats.estimatedRelError = estimate.relError;
    stats.probePixels = estimate.probePixels;
    stats.estimateBalanced = estimate.available && (estimate.probePixels > 0 || halvesBalanced(limits.cyclePasses, done));

    // The output: the partial file, or the image resolved into the capacity reserved above. The backend's
    // accumulation goes first: room for the writer's buffer.
    std::string error;
    const auto writeStart = std::chrono::steady_clock::now();
    if (partial) {
        PartialHeader header;
        header.fingerprint = fingerprint;
        header.fingerprint.width = stats.width;
        header.fingerprint.height = stats.height;
        header.fingerprint.seed = options.seed;
        header.fingerprint.blocks = stats.blocks;
        header.fingerprint.fullCycle = stats.fullCycle;
        header.fingerprint.version = "trazo " TRAZO_VERSION;
        header.passes = {done};
        header.requested = openEndedPartial ? done : range;
        header.rays = outcome.rays;
        header.seconds = outcome.seconds;
        header.backend = describeBackend(*backend, "");
        backend.reset();
        if (!writePartialFile(options.partialPath, header, accum, error)) {
            std::fprintf(stderr, "trazo: %s\n", error.c_str());
            return 1;
        }
        if (openEndedPartial)
            std::fprintf(stderr, "trazo: stopped by --time after passes %s: wrote them to %s\n",
                         formatRange(done).c_str(), options.partialPath.c_str());
        else if (done != header.requested || signalled)
            std::fprintf(stderr, "trazo: %s after passes %s of %s: wrote them to %s\n",
                         signalled ? ("stopped by signal " + std::to_string((int)stopSignal)).c_str()
                                   : "stopped by --time",
                         formatRange(done).c_str(), formatRange(range).c_str(), options.partialPath.c_str());
    } else {
        backend.reset();
        for (const AccumPixel& p : accum) image.push_back(p.estimate());  // resolveImage, into the reserved image
        std::vector<AccumPixel>().swap(accum);
        if (!writeImage(options.output, (int)stats.width, (int)stats.height, image, error)) {
            std::fprintf(stderr, "trazo: %s\n", error.c_str());
            return 1;
        }
    }
    stats.writeSeconds = secondsSince(writeStart);

    stats.peakRssMb = peakRssMegabytes();
    if (!options.quiet) std::fputs(formatStatsSummary(stats).c_str(), stderr);
    if (!options.statsPath.empty()) {
        if (!writeTextFileAtomically(options.statsPath, formatStatsJson(stats), error)) {
            std::fprintf(stderr, "trazo: %s\n", error.c_str());
            return 1;
        }
    }
    return signalled ? 3 : 0;  // a signal stops partial renders only
}

}  // namespace

}  // namespace trazo
