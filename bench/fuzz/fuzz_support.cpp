// Shared by the fuzz harnesses: see fuzz_support.h.
#include "fuzz_support.h"

#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <vector>

#include <unistd.h>

#include "backends/backend.h"
#include "flatten/flatten.h"
#include "render/frame_setup.h"
#include "render/progressive_render.h"
#include "render/render_plan.h"
#include "render/strata_plan.h"
#include "scene/scene.h"

#ifndef TRAZO_FUZZ_SCENE_ROOT
#define TRAZO_FUZZ_SCENE_ROOT "."
#endif

namespace trazo::fuzz {

namespace {

// The most rays one input may cost (raysPerPixelPass is an upper estimate): ~0.1 s with sanitizers.
constexpr double kMaxRaysPerInput = 2.0e5;
constexpr uint32_t kTinySide = 8;

std::string gTempDir;
std::vector<std::string> gTempFiles;

void removeTemporaries() {
    for (const std::string& f : gTempFiles) ::unlink(f.c_str());
    if (!gTempDir.empty()) ::rmdir(gTempDir.c_str());
}

}  // namespace

const std::string& sceneRoot() {
    static const std::string root = [] {
        const char* env = std::getenv("TRAZO_FUZZ_ROOT");
        return std::string(env && *env ? env : TRAZO_FUZZ_SCENE_ROOT);
    }();
    return root;
}

std::string privateTempPath(const std::string& suffix) {
    static std::once_flag once;
    std::call_once(once, [] {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/trazo-fuzz-XXXXXX";
        std::vector<char> buffer(pattern.begin(), pattern.end());
        buffer.push_back('\0');
        if (!::mkdtemp(buffer.data())) fail("cannot create a temporary folder from " + pattern);
        gTempDir = buffer.data();
        std::atexit(removeTemporaries);
    });
    const std::string path = gTempDir + "/input" + suffix;
    for (const std::string& f : gTempFiles)
        if (f == path) return path;
    gTempFiles.push_back(path);
    return path;
}

void writeFileOrDie(const std::string& path, const uint8_t* data, size_t size) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) fail("cannot write " + path);
    const bool ok = (size == 0 || std::fwrite(data, 1, size, f) == size);
    if (std::fclose(f) != 0 || !ok) fail("cannot write " + path);
}

bool keptReadContract(bool read, const Diagnostics& diags, const std::string& reader, const std::string& what) {
    if (!read && !diags.hasErrors()) fail(reader + " returned nothing and reported no error");
    if (read && diags.hasErrors()) fail(reader + " returned " + what + " and reported an error");
    return read;
}

Scene stageScene() {
    Scene scene;
    scene.path = sceneRoot() + "/stage.scene";
    scene.settings.renderWidth = int(kTinySide);
    scene.settings.renderHeight = int(kTinySide);
    scene.settings.reflectionQuality = 1;
    scene.settings.indirectQuality = 1;
    scene.settings.reflectionSteps = 2;
    scene.camera.pov = Vec3(0.5f, 1.0f, 6.0f);
    scene.camera.poi = Vec3(0, 0, 0);
    scene.camera.fovDegrees = 40.0f;
    Material m;
    m.name = "fuzz";
    m.reflectionAmount = 0.3f;
    m.reflectionAngleDegrees = 10.0f;
    m.opacity = 0.8f;
    m.refractionIndex = 1.3f;
    scene.materials.push_back(m);
    PointLight point;
    point.position = Vec3(3, 4, 5);
    scene.pointLights.push_back(point);
    AreaLight area;
    area.position = Vec3(0, 4, 0);
    area.subdivisionX = area.subdivisionY = 2;
    scene.areaLights.push_back(area);
    return scene;
}

void renderTiny(const Scene& scene) {
    FlattenResult flat = flatten(scene);
    const StrataBlocks blocks = headlessBlocks(flat.arrays);
    const double rays = raysPerPixelPass(flat.arrays, blocks) * double(kTinySide * kTinySide);
    static const bool verbose = std::getenv("TRAZO_FUZZ_VERBOSE") != nullptr;
    if (verbose) std::fprintf(stderr, "trazo fuzz: %.0f rays estimated%s\n", rays, rays > kMaxRaysPerInput ? ", render skipped" : "");
    if (rays > kMaxRaysPerInput) return;
    std::unique_ptr<Backend> backend = createCpuBackend(1);
    backend->uploadMoved(std::move(flat.arrays));
    backend->resize(kTinySide, kTinySide);
    const FrameParams frame = makeFrameParams(scene, kTinySide, kTinySide, 1, blocks);
    RenderLimits limits;
    limits.passes = 1;
    renderProgressive(*backend, frame, limits);
    const std::vector<Vec3> image = readImage(*backend);
    if (image.size() != size_t(kTinySide) * kTinySide) fail("the tiny render read back a wrong-sized image");
}

void fail(const std::string& what) {
    std::fprintf(stderr, "trazo fuzz: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

}  // namespace trazo::fuzz
