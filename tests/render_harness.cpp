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
    if (request.allFeatures) flat.arrays.features |= kSpecialisedFeatures;
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

// Rounded from double, so a coordinate's only new error is its final rounding to float.
Vec3 scaled(Vec3 p, double factor) { return Vec3(float(p.x * factor), float(p.y * factor), float(p.z * factor)); }
float scaled(float v, double factor) { return float(v * factor); }

void appendUniformScale(std::vector<TransformStep>& steps, double factor) {
    const float f = float(factor);
    steps.push_back({TransformStep::Kind::Scale, Vec3(f, f, f), 0.0f});  // the last step acts on the world
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
    const auto scale = [factor](auto& value) { value = scaled(value, factor); };
    scale(scene.camera.pov);
    scale(scene.camera.poi);
    for (Sphere& sphere : scene.spheres) {
        scale(sphere.center);
        scale(sphere.radius);
    }
    for (Box& box : scene.boxes) appendUniformScale(box.transforms, factor);
    for (Cylinder& cylinder : scene.cylinders) {
        scale(cylinder.base);
        scale(cylinder.height);
        scale(cylinder.radius);
    }
    for (Mesh& mesh : scene.meshes) appendUniformScale(mesh.transforms, factor);
    for (Csg& csg : scene.csgs) appendUniformScale(csg.transforms, factor);
    for (PointLight& light : scene.pointLights) scale(light.position);
    for (AreaLight& light : scene.areaLights) {
        scale(light.position);
        scale(light.width);
        scale(light.height);
    }
}

double rmse(const RenderedImage& a, const RenderedImage& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const Vec3 d = a.pixels[i] - b.pixels[i];
        sum += double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
    }
    return std::sqrt(sum / (3.0 * a.pixels.size()));
}

}  // namespace trazo::test
