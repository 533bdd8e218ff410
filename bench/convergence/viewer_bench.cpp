// viewer_bench: the viewer's image against time, with and without growing blocks (ViewerSession, the viewer's
// own model, driven as the window does: batches sized to its 1/30 s budget). Prints the relative error against
// a converged reference at 0.25, 0.5, 1, 2, 4 … seconds for both.
//   viewer_bench SCENE [--seconds S] [--width W] [--height H] [--threads N]
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "model/viewer_session.h"
#include "render/error_estimate.h"
#include "render/frame_setup.h"
#include "render/progressive_render.h"
#include "scene/scene_reader.h"

namespace {

using namespace trazo;
using Clock = std::chrono::steady_clock;


struct Reading {
    double seconds, relError;
    uint32_t passes;
    double samples;
    std::string blocks;
};

std::vector<Reading> run(const Scene& scene, const std::vector<Vec3>& reference, uint32_t width, uint32_t height,
                         unsigned threads, bool grow, double seconds) {
    ViewerSession session(scene, createCpuBackend(threads), 1, width, height);
    session.setBlocks(StrataBlocks::ones(), grow ? ViewerSession::kBatchSeconds : 0.0);
    std::vector<Reading> out;
    const auto start = Clock::now();
    double next = 0.25;
    for (;;) {
        session.renderPasses(session.passesForBudget(ViewerSession::kBatchSeconds));
        const double t = std::chrono::duration<double>(Clock::now() - start).count();
        if (t < next) continue;
        const ReferenceError e = compareToReference(session.image(), reference);
        const ProgressiveAccumulation& a = session.accumulation();
        out.push_back({t, e.relError, a.passes(), a.samples(), describeBlocks(a.blocks())});
        next *= 2;
        if (next > seconds) break;
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    std::string path;
    double seconds = 4;
    uint32_t width = 0, height = 0;
    unsigned threads = 0;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--seconds") && i + 1 < argc) seconds = std::stod(argv[++i]);
        else if (!std::strcmp(argv[i], "--width") && i + 1 < argc) width = std::stoul(argv[++i]);
        else if (!std::strcmp(argv[i], "--height") && i + 1 < argc) height = std::stoul(argv[++i]);
        else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) threads = std::stoul(argv[++i]);
        else path = argv[i];
    }
    if (path.empty()) {
        std::fprintf(stderr, "usage: viewer_bench SCENE [--seconds S] [--width W] [--height H] [--threads N]\n");
        return 2;
    }
    Diagnostics diags;
    const Scene scene = readSceneFile(path, diags);
    printDiagnostics(diags);
    if (diags.hasErrors()) return 2;
    if (!width) width = scene.settings.renderWidth;
    if (!height) height = scene.settings.renderHeight;

    // Reference: the headless default's blocks, 256 of its complete estimates, another seed.
    const FlattenResult flat = flatten(scene);
    std::unique_ptr<Backend> backend = createCpuBackend(threads);
    backend->upload(flat.arrays);
    backend->resize(width, height);
    const StrataBlocks blocks = headlessBlocks(flat.arrays);
    RenderLimits limits;
    limits.passes = 256 * cameraPathPasses(flat.arrays, blocks);
    renderProgressive(*backend, makeFrameParams(scene, width, height, 999, blocks), limits);
    const std::vector<Vec3> reference = readImage(*backend);

    std::printf("# %s, %ux%u, cpu: relative error against a %u-pass reference (blocks %s)\n", path.c_str(), width,
                height, limits.passes, describeBlocks(blocks).c_str());
    std::printf("| blocks | seconds | passes | one-stratum samples | rel. error | blocks now |\n");
    std::printf("|---|---|---|---|---|---|\n");
    for (bool grow : {false, true}) {
        for (const Reading& r : run(scene, reference, width, height, threads, grow, seconds))
            std::printf("| %s | %.2f | %u | %.0f | %.3f%% | %s |\n", grow ? "growing" : "one stratum", r.seconds,
                        r.passes, r.samples, 100 * r.relError, r.blocks.c_str());
    }
    return 0;
}
