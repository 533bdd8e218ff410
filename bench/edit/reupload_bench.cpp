// What an edit costs in the viewer (issue 15): a scene with a large mesh and a sphere; a full flatten + upload
// against moving the sphere (flatten reusing the mesh, upload of the changed arrays only), the time from the
// edit to the first preview pass at several preview divisors, and the picking queries, on the CPU backend or
// another (`--backend cuda`: the viewer's own on a GPU machine).
//   reupload_bench SCENE [--threads N] [--repeat R] [--backend cpu|cuda]
// SCENE: e.g. the big_mesh.scene of bench/scene_creation/make_big_mesh.sh (one 1M-triangle mesh); a sphere
// is added beside whatever it holds.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "flatten/flatten.h"
#include "model/viewer_session.h"
#include "scene/scene_reader.h"

using namespace trazo;

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// Moves the sphere back and forth (so the scene's bounds stay put) and applies the edit.
void moveSphere(ViewerSession& session, int step) {
    session.scene().spheres.back().center.x += (step % 2 ? -0.05f : 0.05f);
    session.markDirty(kDirtyScene);
    session.applyEdits();
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: reupload_bench SCENE [--threads N] [--repeat R] [--backend cpu|cuda]\n");
        return 2;
    }
    unsigned threads = 0;
    int repeat = 5;
    BackendChoice choice = BackendChoice::Cpu;
    for (int i = 2; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--threads")) threads = unsigned(std::atoi(argv[i + 1]));
        else if (!std::strcmp(argv[i], "--repeat")) repeat = std::max(1, std::atoi(argv[i + 1]));
        else if (!std::strcmp(argv[i], "--backend"))
            choice = !std::strcmp(argv[i + 1], "cuda") ? BackendChoice::Cuda : BackendChoice::Cpu;
    }
    auto makeBackend = [&] {
        std::string why;
        std::unique_ptr<Backend> backend = createBackend(choice, threads, why);
        if (!backend) {
            std::fprintf(stderr, "reupload_bench: %s\n", why.c_str());
            std::exit(1);
        }
        return backend;
    };
    Diagnostics diags;
    Scene scene = readSceneFile(argv[1], diags);
    if (diags.hasErrors()) {
        printDiagnostics(diags);
        return 2;
    }
    scene.settings.renderWidth = scene.settings.renderHeight = 512;
    scene.spheres.push_back(Sphere{kDefaultMaterial, Vec3(1.35f, 0.9f, 0.0f), 0.25f, {}});
    size_t triangles = 0;
    for (const Mesh& m : scene.meshes) triangles += m.data ? m.data->corners.size() / 3 : 0;
    std::printf("scene %s: %zu triangles in %zu meshes, %zu spheres\n", argv[1], triangles, scene.meshes.size(),
                scene.spheres.size());

    // Full: what every edit cost before (flatten from scratch, upload everything to a fresh backend).
    std::vector<double> fullFlatten, fullUpload;
    for (int r = 0; r < repeat; ++r) {
        std::unique_ptr<Backend> backend = makeBackend();
        const auto t0 = Clock::now();
        const FlattenResult flat = flatten(scene);
        fullFlatten.push_back(secondsSince(t0));
        const auto t1 = Clock::now();
        backend->upload(flat.arrays);
        fullUpload.push_back(secondsSince(t1));
    }
    std::printf("full flatten + upload:      flatten %8.2f ms  upload %8.2f ms  (median of %d)\n",
                1e3 * median(fullFlatten), 1e3 * median(fullUpload), repeat);

    ViewerSession session(scene, makeBackend(), 0, 512, 512);
    std::printf("backend: %s\n", session.backend().deviceName().c_str());
    session.renderPasses(1);
    std::vector<double> flattenS, compareS, uploadS, apply;
    for (int r = 0; r < repeat; ++r) {
        const auto t0 = Clock::now();
        moveSphere(session, r);
        apply.push_back(secondsSince(t0));
        const UploadReport& u = session.lastUpload();
        flattenS.push_back(u.flattenSeconds);
        compareS.push_back(u.compareSeconds);
        uploadS.push_back(u.uploadSeconds);
        if (r == 0)
            std::printf("sphere moved: re-sent [%s], meshes rebuilt %u, reused %u\n", describeArrays(u.changed).c_str(),
                        u.meshesRebuilt, u.meshesReused);
    }
    std::printf("sphere moved (reuse):       flatten %8.2f ms  compare %6.2f ms  upload %8.2f ms  applyEdits %8.2f ms\n",
                1e3 * median(flattenS), 1e3 * median(compareS), 1e3 * median(uploadS), 1e3 * median(apply));

    // From the edit to the first preview pass, at the viewer's preview divisors.
    for (uint32_t divisor : {1u, 2u, 4u, 8u}) {
        session.setPreviewDivisor(divisor);
        session.renderPasses(1);
        std::vector<double> toPreview, pass;
        for (int r = 0; r < repeat; ++r) {
            const auto t0 = Clock::now();
            moveSphere(session, r);
            const auto t1 = Clock::now();
            session.renderPasses(1);
            pass.push_back(secondsSince(t1));
            toPreview.push_back(secondsSince(t0));
        }
        std::printf("edit -> first pass at %4ux%-4u (1/%u): %8.2f ms (the pass alone %8.2f ms)\n", session.width(),
                    session.height(), divisor, 1e3 * median(toPreview), 1e3 * median(pass));
    }
    session.setPreviewDivisor(1);

    // A mesh moved: its BVH is rebuilt (the comparison case).
    if (!session.scene().meshes.empty()) {
        session.scene().meshes[0].transforms.push_back({TransformStep::Kind::Translation, Vec3(0, 0.01f, 0), 0.0f});
        session.markDirty(kDirtyScene);
        const auto t0 = Clock::now();
        session.applyEdits();
        const double s = secondsSince(t0);
        const UploadReport& u = session.lastUpload();
        std::printf("mesh moved: re-sent [%s], meshes rebuilt %u; flatten %.2f ms compare %.2f ms upload %.2f ms "
                    "applyEdits %.2f ms\n",
                    describeArrays(u.changed).c_str(), u.meshesRebuilt, 1e3 * u.flattenSeconds, 1e3 * u.compareSeconds,
                    1e3 * u.uploadSeconds, 1e3 * s);
    }

    // Picking: one ray, and the selection outline's object ids at 512 × 512.
    std::vector<double> pickS, idsS;
    for (int r = 0; r < repeat; ++r) {
        auto t0 = Clock::now();
        (void)session.pick(256.0f, 256.0f);
        pickS.push_back(secondsSince(t0));
        t0 = Clock::now();
        const std::vector<int32_t> ids = session.objectIds(512, 512);
        idsS.push_back(secondsSince(t0));
    }
    std::printf("pick: %.3f ms; objectIds(512, 512): %.2f ms\n", 1e3 * median(pickS), 1e3 * median(idsS));

    // One convergence point's cost at 512 × 512: the accumulation read back and estimateError.
    std::vector<double> estimateS;
    for (int r = 0; r < repeat; ++r) {
        const auto t0 = Clock::now();
        std::vector<AccumPixel> accum;
        session.backend().readAccumulation(accum);
        (void)estimateError(accum);
        estimateS.push_back(secondsSince(t0));
    }
    std::printf("error estimate at %ux%u: %.2f ms\n", session.width(), session.height(), 1e3 * median(estimateS));
    return 0;
}
