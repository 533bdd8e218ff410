// trazo_bench: time, Mrays/s and error of seed scenes at their own settings, per backend, next to the
// thesis's GTX 560 figures. Usage: trazo_bench [--threads N] [--reference-cycles K] [--passes P] SCENE...
// Renders what `trazo --render SCENE` does: the headless blocks (headlessBlocks), one cycle of the camera-path
// grids; --passes P renders P such passes instead (e.g. for instruction counts under callgrind).
// Error: RMSE (and relative RMSE) of that image against a K-times-longer reference of the same backend
// with another seed; K = 0 skips it. "all-features s" renders the same passes with the unspecialised
// (all-features) instance of renderSample, so the last column is what feature specialisation saves.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "flatten/flatten.h"
#include "integrator/sample_variants.h"
#include "render/frame_setup.h"
#include "render/progressive_render.h"
#include "scene/scene_reader.h"

namespace {

using namespace trazo;

struct Thesis {
    const char* scene;
    double seconds;
};
// results.csv of the seed (GTX 560, 512², Antialiasing 1): execution time of the render phase.
const Thesis kThesis[] = {{"scene1_area", 0.5203},  {"scene1_point", 0.1981}, {"scene4_reflect", 0.5544},
                          {"scene6_glossy", 8.2046}, {"scene7_refract", 0.6008}, {"scene3_csg_area", 15.7502},
                          {"scene3_csg", 0.4630}};

double thesisSeconds(const std::string& path) {
    for (const Thesis& t : kThesis) {
        const std::string name = std::string("/") + t.scene + ".scene";
        if (path.size() >= name.size() && path.compare(path.size() - name.size(), name.size(), name) == 0)
            return t.seconds;
    }
    return 0;
}

std::vector<Vec3> render(Backend& b, const Scene& scene, const StrataBlocks& blocks, uint32_t passes, uint32_t seed,
                         RenderOutcome& outcome) {
    const FrameParams frame =
        makeFrameParams(scene, scene.settings.renderWidth, scene.settings.renderHeight, seed, blocks);
    b.reset();
    RenderLimits limits;
    limits.passes = passes;
    outcome = renderProgressive(b, frame, limits);
    return readImage(b);
}

}  // namespace

int main(int argc, char** argv) {
    unsigned threads = 0;
    uint32_t referenceCycles = 4;
    uint32_t fixedPasses = 0;
    std::vector<std::string> scenes;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) threads = std::stoul(argv[++i]);
        else if (!std::strcmp(argv[i], "--reference-cycles") && i + 1 < argc) referenceCycles = std::stoul(argv[++i]);
        else if (!std::strcmp(argv[i], "--passes") && i + 1 < argc) fixedPasses = std::stoul(argv[++i]);
        else scenes.push_back(argv[i]);
    }
    if (scenes.empty()) {
        std::fprintf(stderr, "usage: trazo_bench [--threads N] [--reference-cycles K] SCENE...\n");
        return 2;
    }

    std::vector<BackendChoice> choices{BackendChoice::Cpu};
    std::string device;
    if (cudaDeviceAvailable(device)) choices.push_back(BackendChoice::Cuda);
    else std::printf("# no CUDA device (%s): CPU only\n", device.c_str());

    std::printf("| scene | backend | device | size | passes | render s | Mrays/s | rays/pixel | RMSE | rel. RMSE | thesis s (GTX 560) | all-features s | specialised speed-up |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const std::string& path : scenes) {
        Diagnostics diags;
        const Scene scene = readSceneFile(path, diags);
        if (diags.hasErrors()) {
            printDiagnostics(diags);
            return 2;
        }
        const FlattenResult flat = flatten(scene);
        const StrataBlocks blocks = headlessBlocks(flat.arrays);
        const uint32_t cycle = fixedPasses ? fixedPasses : cameraPathPasses(flat.arrays, blocks);
        for (BackendChoice choice : choices) {
            std::string error;
            auto backend = createBackend(choice, threads, error);
            backend->upload(flat.arrays);
            backend->resize(scene.settings.renderWidth, scene.settings.renderHeight);
            RenderOutcome timed, ref;
            render(*backend, scene, blocks, 1, 0, timed);  // warm-up (CUDA context, caches)
            const std::vector<Vec3> image = render(*backend, scene, blocks, cycle, 1, timed);
            double rmse = NAN, relative = NAN;
            if (referenceCycles > 0) {
                const std::vector<Vec3> reference = render(*backend, scene, blocks, cycle * referenceCycles, 2, ref);
                double se = 0, mean = 0;
                for (size_t i = 0; i < image.size(); ++i) {
                    const Vec3 d = image[i] - reference[i];
                    se += double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
                    mean += (double(reference[i].x) + reference[i].y + reference[i].z) / 3.0;
                }
                rmse = std::sqrt(se / (3.0 * image.size()));
                relative = rmse / (mean / image.size());
            }
            SceneArrays oracleArrays = flat.arrays;
            oracleArrays.features |= kAllSampleFeatures;
            RenderOutcome oracle;
            backend->upload(oracleArrays);
            render(*backend, scene, blocks, cycle, 1, oracle);
            backend->upload(flat.arrays);
            const double pixels = double(scene.settings.renderWidth) * scene.settings.renderHeight;
            std::printf("| %s | %s | %s | %dx%d | %u | %.4f | %.2f | %.1f | %.5f | %.4f | %.4f | %.4f | %.3f |\n",
                        path.c_str(),
                        backend->name().c_str(), backend->deviceName().c_str(), scene.settings.renderWidth,
                        scene.settings.renderHeight, timed.passes, timed.seconds, timed.rays / timed.seconds * 1e-6,
                        timed.rays / pixels, rmse, relative, thesisSeconds(path), oracle.seconds,
                        oracle.seconds / timed.seconds);
            std::fflush(stdout);
        }
    }
    return 0;
}
