// Tests of the viewer session's support for editing: picking through the backend's ray query (against closed
// forms), which arrays each kind of edit re-sends, replacing the scene, and the convergence estimate.
#include "model/viewer_session.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "render/frame_setup.h"
#include "render/progressive_render.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace trazo {
namespace {

// Two spheres (one partly in front of the other) and a unit box moved to [2,3]×[-2,-1]×[-0.5,0.5], seen
// from +Z; a point light so it renders.
Scene pickScene() {
    Scene s;
    s.settings.renderWidth = 32;
    s.settings.renderHeight = 24;
    s.settings.indirectQuality = 0;
    s.camera.pov = Vec3(0, 0, 10);
    s.camera.poi = Vec3(0, 0, 0);
    s.camera.fovDegrees = 45.0f;
    s.spheres.push_back(Sphere{kDefaultMaterial, Vec3(0, 0, 0), 1.0f, {}});
    s.spheres.push_back(Sphere{kDefaultMaterial, Vec3(1.2f, 0.6f, 2.0f), 0.5f, {}});
    Box box;
    box.transforms.push_back({TransformStep::Kind::Translation, Vec3(2.5f, -1.5f, 0), 0.0f});
    s.boxes.push_back(box);
    s.pointLights.push_back(PointLight{Vec3(0, 5, 5), Vec3(1), {}});
    return s;
}

// The closed forms: nearest hit of the ray among pickScene's shapes; `clear` is false near a silhouette,
// where float rounding may decide either way.
struct Expected {
    bool hit = false;
    ObjectId object;
    float t = INFINITY;
    bool clear = true;
};

Expected closedForm(const Scene& s, const Ray& ray) {
    Expected e;
    for (uint32_t i = 0; i < s.spheres.size(); ++i) {
        const Vec3 oc = ray.origin - s.spheres[i].center;
        const double b = dot(oc, ray.direction), r2 = double(s.spheres[i].radius) * s.spheres[i].radius;
        const double disc = b * b - (dot(oc, oc) - r2);
        if (std::fabs(disc) < 1e-3 * r2) e.clear = false;
        if (disc < 0) continue;
        const double t = -b - std::sqrt(disc);
        if (t > 0 && t < e.t) e = Expected{true, ObjectId{ObjectId::Kind::Sphere, i}, float(t), e.clear};
    }
    // The box: slabs.
    const Vec3 lo(2, -2, -0.5f), hi(3, -1, 0.5f);
    double tNear = -INFINITY, tFar = INFINITY;
    for (int k = 0; k < 3; ++k) {
        const double t0 = (lo[k] - ray.origin[k]) / ray.direction[k], t1 = (hi[k] - ray.origin[k]) / ray.direction[k];
        tNear = std::max(tNear, std::min(t0, t1));
        tFar = std::min(tFar, std::max(t0, t1));
    }
    if (std::fabs(tFar - tNear) < 1e-3) e.clear = false;
    if (tNear <= tFar && tNear > 0 && tNear < e.t) e = Expected{true, ObjectId{ObjectId::Kind::Box, 0}, float(tNear), e.clear};
    return e;
}

TEST(ViewerSessionPick, EveryPixelPicksWhatTheClosedFormsSay) {
    const Scene scene = pickScene();
    ViewerSession session(scene, createCpuBackend(2), 0);
    const CameraFrame camera = makeCameraFrame(scene.camera.pov, scene.camera.poi, scene.camera.fovDegrees, 32, 24);
    int hits = 0, misses = 0, frontSphere = 0;
    for (uint32_t y = 0; y < 24; ++y) {
        for (uint32_t x = 0; x < 32; ++x) {
            const float px = x + 0.5f, py = y + 0.5f;
            const Ray ray = generateCameraRay(camera, px, py);
            const Expected want = closedForm(scene, ray);
            if (!want.clear) continue;
            const std::optional<PickHit> got = session.pick(px, py);
            ASSERT_EQ(got.has_value(), want.hit) << x << "," << y;
            if (!want.hit) {
                ++misses;
                continue;
            }
            ++hits;
            if (want.object == ObjectId{ObjectId::Kind::Sphere, 1}) ++frontSphere;
            EXPECT_EQ(got->object, want.object) << x << "," << y;
            EXPECT_NEAR(got->t, want.t, 1e-4f * want.t) << x << "," << y;
            const Vec3 point = ray.origin + ray.direction * want.t;
            EXPECT_NEAR(length(got->point - point), 0.0f, 1e-3f);
        }
    }
    EXPECT_GT(hits, 40);
    EXPECT_GT(misses, 300);
    EXPECT_GT(frontSphere, 3);  // the sphere in front wins where both are hit
}

TEST(ViewerSessionPick, ObjectIdsAgreeWithPickAtEveryPixel) {
    Scene scene = pickScene();
    scene.areaLights.push_back(AreaLight{});  // a visible rectangle facing the camera, left of the spheres
    scene.areaLights[0].position = Vec3(-3, 1, 0);
    scene.areaLights[0].direction = Vec3(0, 0, 1);
    ViewerSession session(scene, createCpuBackend(2), 0, 32, 24);
    const std::vector<int32_t> ids = session.objectIds(32, 24);
    ASSERT_EQ(ids.size(), 32u * 24u);
    int light = 0;
    for (uint32_t y = 0; y < 24; ++y) {
        for (uint32_t x = 0; x < 32; ++x) {
            const std::optional<PickHit> hit = session.pick(x + 0.5f, y + 0.5f);
            const std::optional<ObjectId> mapped = session.objectOf(ids[y * 32 + x]);
            ASSERT_EQ(hit.has_value(), mapped.has_value()) << x << "," << y;
            if (hit) {
                EXPECT_EQ(hit->object, *mapped) << x << "," << y;
            }
            if (mapped && *mapped == ObjectId{ObjectId::Kind::AreaLight, 0}) ++light;
        }
    }
    EXPECT_GT(light, 4);
    // The selection's mask holds exactly the pixels that pick the object.
    const ObjectId box{ObjectId::Kind::Box, 0};
    const std::vector<uint8_t> mask = session.selectionMask(ids, box);
    for (size_t i = 0; i < ids.size(); ++i) EXPECT_EQ(mask[i] == 1, session.objectOf(ids[i]) == box);
    EXPECT_GT(std::count(mask.begin(), mask.end(), 1), 4);
}

TEST(ViewerSessionPick, PicksFollowEditsAndMissesAreEmpty) {
    ViewerSession session(pickScene(), createCpuBackend(2), 0);
    EXPECT_FALSE(session.pick(0.5f, 0.5f).has_value());  // a corner: background
    ASSERT_TRUE(session.pick(16.0f, 12.0f).has_value());
    EXPECT_EQ(session.pick(16.0f, 12.0f)->object, (ObjectId{ObjectId::Kind::Sphere, 0}));
    session.scene().spheres[0].center = Vec3(0, -100, 0);  // pending: pick applies it first
    session.markDirty(kDirtyScene);
    EXPECT_FALSE(session.pick(16.0f, 12.0f).has_value());
}

// The CUDA backend's object queries (rayAnswerKernel) and partial uploads give the CPU's answers.
TEST(ViewerSessionPick, CudaAnswersTheSameObjects) {
    std::string why;
    std::unique_ptr<Backend> cuda = createBackend(BackendChoice::Cuda, 0, why);
    if (!cuda) GTEST_SKIP() << "no CUDA backend: " << why;
    ViewerSession onCpu(pickScene(), createCpuBackend(2), 0), onGpu(pickScene(), std::move(cuda), 0);
    for (int edit = 0; edit < 2; ++edit) {
        EXPECT_EQ(onCpu.objectIds(64, 48), onGpu.objectIds(64, 48)) << "edit " << edit;
        for (ViewerSession* s : {&onCpu, &onGpu}) {  // a partial upload: spheres and topNodes
            s->scene().spheres[1].center.x -= 0.7f;
            s->markDirty(kDirtyScene);
            s->applyEdits();
        }
        EXPECT_EQ(onGpu.lastUpload().changed, onCpu.lastUpload().changed);
    }
}

// A sphere, a cylinder, a 2-triangle mesh, lights, two materials: every kind of edit the panels make.
Scene editScene() {
    Scene s = pickScene();
    s.materials.push_back(Material{});
    s.materials[0].name = "m";
    s.spheres[0].material = 0;
    auto data = std::make_shared<MeshData>();
    data->positions = {{-4, -3, 0}, {-2, -3, 0}, {-2, -1, 0}};
    data->corners = {{0, -1, -1}, {1, -1, -1}, {2, -1, -1}};
    Mesh mesh;
    mesh.data = data;
    s.meshes.push_back(mesh);
    s.areaLights.push_back(AreaLight{});
    s.areaLights[0].position = Vec3(0, 4, 0);
    return s;
}

struct EditCase {
    const char* what;
    DirtyFlags flags;
    std::function<void(Scene&)> edit;
    const char* changed;  // describeArrays of what must be re-sent
};

TEST(ViewerSessionUpload, EachKindOfEditResendsExactlyItsArrays) {
    const std::vector<EditCase> cases = {
        {"camera", kDirtyCamera, [](Scene& s) { s.camera.pov.x += 1.0f; }, "none"},
        {"material colour", kDirtyScene, [](Scene& s) { s.materials[0].diffuseColor = Vec3(0.2f, 0.3f, 0.4f); }, "materials"},
        // Stays the top level's second leaf entry: the order of objects holds, its node bounds change.
        {"sphere moved", kDirtyScene, [](Scene& s) { s.spheres[1].center.y += 0.1f; }, "spheres topNodes"},
        {"mesh moved", kDirtyScene,
         [](Scene& s) { s.meshes[0].transforms.push_back({TransformStep::Kind::Translation, Vec3(0, 0.1f, 0), 0.0f}); },
         "meshNodes triangles topNodes"},  // a translation leaves normals, tangents and uvs (the corners) as they were
        {"point light", kDirtyScene, [](Scene& s) { s.pointLights[0].position.x = 1.0f; }, "pointLights"},
        {"area light", kDirtyScene, [](Scene& s) { s.areaLights[0].width = 2.0f; }, "areaLights"},
        // BackgroundColor is the environment's radiance too (SPEC §7): its array goes with the settings.
        {"setting", kDirtyScene, [](Scene& s) { s.settings.backgroundColor = Vec3(0.1f); }, "environment values"},
        {"exposure", kDirtyScene, [](Scene& s) { s.settings.exposure = 1.0f; }, "none"},
        // A top level one object larger or smaller: its depth, and so traversalStackNeed (a value), changes too.
        {"sphere added", kDirtyScene, [](Scene& s) { s.spheres.push_back(Sphere{kDefaultMaterial, Vec3(-1, 2, 0), 0.3f, {}}); },
         "spheres objects topNodes values"},
        {"sphere deleted", kDirtyScene, [](Scene& s) { s.spheres.erase(s.spheres.begin() + 1); },
         "spheres objects topNodes values"},
    };
    for (const EditCase& c : cases) {
        ViewerSession session(editScene(), createCpuBackend(2), 0, 16, 12);
        session.renderPasses(2);
        const uint32_t stackBefore = session.arrays().traversalStackNeed;
        c.edit(session.scene());
        session.markDirty(c.flags);
        session.applyEdits();
        const UploadReport& r = session.lastUpload();
        if (std::string(c.what).find("sphere ") == 0 && std::string(c.what) != "sphere moved") {
            EXPECT_NE(session.arrays().traversalStackNeed, stackBefore) << c.what;
        }
        EXPECT_EQ(describeArrays(r.changed), c.changed) << c.what;
        EXPECT_EQ(r.meshesRebuilt, std::string(c.what) == "mesh moved" ? 1u : 0u) << c.what;
        if (c.flags == kDirtyScene && std::string(c.what) != "mesh moved") {
            EXPECT_EQ(r.meshesReused, 1u) << c.what;
        }
        // What the backend now holds renders exactly what a fresh session of the edited scene renders.
        session.renderPasses(3);
        ViewerSession fresh(session.scene(), createCpuBackend(2), 0, 16, 12);
        fresh.renderPasses(3);
        const std::vector<Vec3> a = session.image(), b = fresh.image();
        EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)), 0) << c.what;
    }
}

TEST(ViewerSessionScene, ReplaceSceneUploadsItWholeAndTakesItsSize) {
    ViewerSession session(pickScene(), createCpuBackend(2), 0);
    session.renderPasses(2);
    const Scene next = test::readSourceScene("scenes/scene1_area.scene");
    session.replaceScene(next);
    EXPECT_EQ(session.renderWidth(), uint32_t(next.settings.renderWidth));
    EXPECT_EQ(session.accumulation().passes(), 0u);
    EXPECT_EQ(session.lastUpload().changed, kAllArrays);
    EXPECT_EQ(session.fileScene().spheres.size(), next.spheres.size());
    EXPECT_EQ(session.dirty(), kDirtyNone);
    session.replaceScene(pickScene(), true);  // keeps 512 × 512
    EXPECT_EQ(session.renderWidth(), uint32_t(next.settings.renderWidth));
    session.setRenderSize(24, 16);
    session.replaceScene(next, true);
    session.renderPasses(3);
    // The same image as a session that started with it.
    ViewerSession fresh(next, createCpuBackend(2), 0, 24, 16);
    fresh.renderPasses(3);
    const std::vector<Vec3> a = session.image(), b = fresh.image();
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)), 0);
}

// scene1_area's cycle is 100 passes (its 10 × 10 light): estimates come at 200, 400, ... passes.
TEST(ViewerSessionConvergence, EstimatesAtEvenCyclesEqualEstimateError) {
    ViewerSession session(test::readSourceScene("scenes/scene1_area.scene"), createCpuBackend(2), 0, 8, 8);
    ASSERT_EQ(session.accumulation().cyclePasses(), 100u);
    EXPECT_TRUE(session.accumulation().convergence().empty());
    session.renderPasses(150);  // an estimate is due: no batch crosses pass 200
    EXPECT_TRUE(session.accumulation().convergence().empty());
    EXPECT_FALSE(session.accumulation().errorEstimate().available);
    session.renderPasses(150);
    EXPECT_EQ(session.accumulation().passes(), 200u);
    ASSERT_EQ(session.accumulation().convergence().size(), 1u);
    std::vector<AccumPixel> accum;
    session.backend().readAccumulation(accum);
    const ErrorEstimate direct = estimateError(accum);
    ASSERT_TRUE(direct.available);
    EXPECT_EQ(session.accumulation().errorEstimate().relError, direct.relError);
    EXPECT_EQ(session.accumulation().convergence()[0].relError, direct.relError);
    EXPECT_EQ(session.accumulation().convergence()[0].passes, 200u);
    EXPECT_EQ(session.accumulation().convergence()[0].seconds, session.accumulation().renderSeconds());
    // A reset empties the series.
    session.scene().camera.pov.x += 0.5f;
    session.markDirty(kDirtyCamera);
    session.applyEdits();
    EXPECT_TRUE(session.accumulation().convergence().empty());
    EXPECT_FALSE(session.accumulation().errorEstimate().available);
}

TEST(ViewerSessionConvergence, TargetErrorStopsTheBatches) {
    ViewerSession session(test::readSourceScene("scenes/scene1_area.scene"), createCpuBackend(2), 0, 8, 8);
    session.setTargetError(1e-9);  // out of reach: passes go on past the first estimate
    session.renderPasses(200);
    session.renderPasses(10);
    EXPECT_EQ(session.accumulation().passes(), 210u);
    EXPECT_FALSE(session.accumulation().targetReached());
    const double reached = session.accumulation().errorEstimate().relError;
    ASSERT_GT(reached, 0.0);
    session.setTargetError(reached * 1.01);  // the estimate in hand already meets it
    EXPECT_TRUE(session.accumulation().targetReached());
    session.renderPasses(10);
    EXPECT_EQ(session.accumulation().passes(), 210u);
    // After a reset, batches run until an estimate meets the target again.
    session.markDirty(kDirtyCamera);
    session.applyEdits();
    EXPECT_FALSE(session.accumulation().targetReached());
    session.setTargetError(10.0);
    for (int i = 0; i < 5; ++i) session.renderPasses(1000);
    EXPECT_TRUE(session.accumulation().targetReached());
    EXPECT_EQ(session.accumulation().passes(), 200u);  // stopped at the first estimate
}

}  // namespace
}  // namespace trazo
