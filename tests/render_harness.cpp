// Test harness implementation: the same pipeline as `trazo --render`, minus the file.
#include "render_harness.h"

#include <cmath>

#include <gtest/gtest.h>

#include "flatten/flatten.h"
#include "integrator/sample_variants.h"
#include "render/frame_setup.h"
#include "render/progressive_render.h"
#include "scene/scene_reader.h"
#include "test_paths.h"

namespace trazo::test {

namespace {

RenderedImage renderScene(Scene& scene, const Diagnostics& diags, const RenderRequest& request) {
    if (diags.hasErrors()) {
        for (const auto& d : diags.items) ADD_FAILURE() << formatDiagnostic(d);
        return {};
    }
    if (request.editScene) request.editScene(scene);
    FlattenResult flat = flatten(scene);
    if (request.allFeatures) flat.arrays.features |= kAllSampleFeatures;
    std::string error;
    auto backend = createBackend(request.backend, request.threads, error);
    if (!backend) {
        ADD_FAILURE() << error;
        return {};
    }
    RenderedImage image;
    image.width = request.width ? request.width : scene.settings.renderWidth;
    image.height = request.height ? request.height : scene.settings.renderHeight;
    backend->upload(flat.arrays);
    backend->resize(image.width, image.height);
    const FrameParams frame = makeFrameParams(scene, image.width, image.height, request.seed, request.blocks);
    RenderLimits limits;
    limits.passes = request.passes;
    if (request.cycleAware) limits.cyclePasses = fullCyclePasses(flat.arrays, request.blocks);
    image.rays = renderProgressive(*backend, frame, limits).rays;
    image.pixels = readImage(*backend);
    return image;
}

}  // namespace

RenderedImage renderSceneText(const std::string& sceneText, const RenderRequest& request) {
    Diagnostics diags;
    Scene scene = readSceneText(sceneText, tempPath("harness.scene"), diags);
    return renderScene(scene, diags, request);
}

RenderedImage renderSceneFile(const std::string& path, const RenderRequest& request) {
    Diagnostics diags;
    Scene scene = readSceneFile(path, diags);
    return renderScene(scene, diags, request);
}

void scaleSceneAboutOrigin(Scene& scene, double factor) {
    // Rounded from double (scene/object_basics.h), so a coordinate's only new error is its final rounding.
    scene.camera.pov = scaledPoint(scene.camera.pov, factor);
    scene.camera.poi = scaledPoint(scene.camera.poi, factor);
#define TRAZO_X(Shape, array, Kind, ...) \
    for (Kind & object : scene.array) scaleAboutOrigin(object, factor);
    TRAZO_OBJECT_KINDS(TRAZO_X)
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
}

void translateScene(Scene& scene, Vec3 delta) {
    scene.camera.pov += delta;
    scene.camera.poi += delta;
#define TRAZO_X(Shape, array, Kind, ...) \
    for (Kind & object : scene.array) translate(object, delta);
    TRAZO_OBJECT_KINDS(TRAZO_X)
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
}

double rmse(const RenderedImage& a, const RenderedImage& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const Vec3 d = a.pixels[i] - b.pixels[i];
        sum += double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
    }
    return std::sqrt(sum / (3.0 * a.pixels.size()));
}

std::string settingsText(int width, int height, int reflectionQuality, int indirectQuality, const std::string& more) {
    return "SceneSettings\n{\nRenderWidth " + std::to_string(width) + "\nRenderHeight " + std::to_string(height) +
           "\nReflectionQuality " + std::to_string(reflectionQuality) + "\nIndirectQuality " +
           std::to_string(indirectQuality) + "\n" + more + "}\n";
}

std::string cameraText(const std::string& pov, const std::string& poi, const std::string& fov) {
    return "Camera\n{\nPOV " + pov + "\nPOI " + poi + "\nFOV " + fov + "\n}\n";
}

std::string blackMaterialText(const std::string& name, const std::string& lines) {
    return "Material\n{\nName " + name + "\nDiffuseColor 0 0 0\nSpecularColor 0 0 0\n" + lines + "}\n";
}

std::string glassSlabBeforeWallText(const std::string& glass, const std::string& thickness, const std::string& wallZ) {
    return blackMaterialText("glass", glass) + blackMaterialText("wall", "EmissiveColor 1 1 1\n") +
           "Box\n{\nMaterial glass\nScale 100 100 " + thickness + "\n}\n" + "Box\n{\nMaterial wall\nTranslation 0 0 " +
           wallZ + "\nScale 1000 1000 1\n}\n";
}

}  // namespace trazo::test
