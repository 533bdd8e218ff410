// Test harness: scene text -> image through the real reader, flatten, CPU backend and resolve.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "core/vec3.h"

namespace trazo {
struct Scene;
}

namespace trazo::test {

struct RenderedImage {
    int width = 0, height = 0;
    std::vector<Vec3> pixels;  // row 0 = top
    uint64_t rays = 0;
    const Vec3& at(int x, int y) const { return pixels[(size_t)y * width + x]; }
};

struct RenderRequest {
    uint32_t passes = 1;
    unsigned threads = 2;
    uint32_t seed = 0;
    BackendChoice backend = BackendChoice::Cpu;
    bool allFeatures = false;  // run the all-features instance of renderSample (the oracle)
    int width = 0, height = 0;  // 0: the scene's RenderWidth/RenderHeight
    StrataBlocks blocks{};      // the strata a pass takes (StrataBlocks::whole(): the thesis's estimator)
    bool cycleAware = false;    // render as the CLI does: halves and strata windows from the scene's cycle
    std::function<void(Scene&)> editScene{};  // applied to the scene as read, before flatten (e.g. a nudge)
};

// Fails the current test (ADD_FAILURE) and returns an empty image when the scene does not read.
RenderedImage renderSceneText(const std::string& sceneText, const RenderRequest& request);
RenderedImage renderSceneFile(const std::string& path, const RenderRequest& request);

// Scales the whole scene (camera, lights, every object) about the origin by `factor`: in exact arithmetic the
// same image (lighting here has no distance falloff), but every non-zero coordinate, and so every float
// operation after it, rounds differently. Exact zeros and axis-aligned directions stay exact.
void scaleSceneAboutOrigin(Scene& scene, double factor);

// Moves the whole scene (camera, lights, every object) by `delta`: in exact arithmetic the same image, but every
// coordinate becomes as large as the move, so every hit point carries its rounding.
void translateScene(Scene& scene, Vec3 delta);

// Root-mean-square difference over all channels.
double rmse(const RenderedImage& a, const RenderedImage& b);

// Scene text block by block (SPEC §3), a parameter a line, for the scenes the suites write.
std::string settingsText(int width, int height, int reflectionQuality, int indirectQuality,
                         const std::string& more = "");  // more: further lines of the block
std::string cameraText(const std::string& pov, const std::string& poi, const std::string& fov);
// A material with no diffuse or specular colour (Kd = Ks = 0): glass, a lamp. `lines`: its other parameters.
std::string blackMaterialText(const std::string& name, const std::string& lines);
// A slab of black material `glass` (its lines after Kd and Ks), 100 × 100 × `thickness` about the origin, before a
// wall that only emits (Ke = 1), 1000 × 1000 × 1 about z = wallZ.
std::string glassSlabBeforeWallText(const std::string& glass, const std::string& thickness, const std::string& wallZ);

}  // namespace trazo::test
