// Tests of what SPEC §7's settings make the viewer redo: Exposure and ViewTransform only the display (the
// accumulation goes on, their undo too); Integrator, MaxBounces, LightSampling, EnvironmentRotation re-flatten
// into the kernels' RenderSettings and restart; the lens re-flattens; the transform the viewer shows.
#include "model/setting_effects.h"

#include <gtest/gtest.h>

#include "model/edit_history.h"
#include "model/viewer_session.h"
#include "scene/block_table.h"

namespace trazo {
namespace {

template <class Target>
const ParamInfo& infoOf(std::span<const ParamSpec<Target>> table, std::string_view name) {
    for (const ParamSpec<Target>& row : table)
        if (row.info.name == name) return row.info;
    ADD_FAILURE() << "no row " << name;
    return table[0].info;
}

TEST(SettingEffects, ExposureAndViewTransformOnlyRedrawTheRestReflattens) {
    const auto settings = [](std::string_view name) { return sceneSettingEffect(infoOf(sceneSettingsTable(), name)); };
    EXPECT_EQ(settings("Exposure"), kDirtyDisplay);
    EXPECT_EQ(settings("ViewTransform"), kDirtyDisplay);
    for (const char* name : {"Integrator", "MaxBounces", "LightSampling", "EnvironmentMap", "EnvironmentRotation",
                             "BackgroundColor", "Antialiasing"})
        EXPECT_EQ(settings(name), kDirtyScene) << name;
    const auto camera = [](std::string_view name) { return cameraSettingEffect(infoOf(cameraTable(), name)); };
    for (const char* name : {"POV", "POI", "FOV"}) EXPECT_EQ(camera(name), kDirtyCamera) << name;
    for (const char* name : {"Aperture", "FocalDistance", "LensQuality"})
        EXPECT_EQ(camera(name), kDirtyCamera | kDirtyScene) << name;
}

TEST(SettingEffects, TheDisplayTransformFollowsExposureViewTransformAndIntegrator) {
    Scene s;
    EXPECT_TRUE(displayTransformOf(s).identity());  // thesis, Auto, 0 stops: §5's bytes
    s.settings.integrator = IntegratorKind::Path;
    EXPECT_TRUE(displayTransformOf(s).srgb);  // Auto under path
    s.settings.viewTransform = ViewTransform::Linear;
    EXPECT_FALSE(displayTransformOf(s).srgb);
    s.settings.exposure = -1.5f;
    EXPECT_FLOAT_EQ(displayTransformOf(s).scale, 0.35355339f);
    s.settings.integrator = IntegratorKind::Thesis;
    s.settings.viewTransform = ViewTransform::Srgb;
    EXPECT_TRUE(displayTransformOf(s).srgb);
}

Scene smallScene() {
    Scene s;
    s.settings.renderWidth = 16;
    s.settings.renderHeight = 12;
    s.settings.indirectQuality = 0;
    s.spheres.push_back(Sphere{kDefaultMaterial, Vec3(0, 0, 0), 1.0f, {}});
    s.pointLights.push_back(PointLight{Vec3(0, 5, 5), Vec3(1), {}});
    return s;
}

TEST(SettingEffects, ADisplayEditKeepsTheAccumulation) {
    ViewerSession session(smallScene(), createCpuBackend(2), 0);
    session.renderPasses(3);  // a batch may end early, where an error estimate is due
    const uint32_t passes = session.accumulation().passes();
    ASSERT_GT(passes, 0u);
    const std::vector<Vec3> before = session.image();
    session.scene().settings.exposure = 2.0f;
    session.scene().settings.viewTransform = ViewTransform::Srgb;
    session.markDirty(kDirtyDisplay);
    EXPECT_EQ(session.dirty(), kDirtyNone);
    session.applyEdits();
    EXPECT_EQ(session.accumulation().passes(), passes);  // not restarted
    const std::vector<Vec3> after = session.image();
    ASSERT_EQ(after.size(), before.size());
    for (size_t i = 0; i < after.size(); ++i) EXPECT_EQ(after[i].x, before[i].x);  // the estimate, untouched
    session.renderPasses(1);
    EXPECT_EQ(session.accumulation().passes(), passes + 1);  // and it goes on
}

TEST(SettingEffects, IntegratorMaxBouncesAndLightSamplingReachTheKernelsAndRestart) {
    ViewerSession session(smallScene(), createCpuBackend(2), 0);
    session.renderPasses(2);
    ASSERT_EQ(session.arrays().settings.integrator, IntegratorKind::Thesis);
    SceneSettings& s = session.scene().settings;
    s.integrator = IntegratorKind::Path;
    s.maxBounces = 5;
    s.lightSampling = LightSampling::Nee;
    session.markDirty(kDirtyScene);
    session.applyEdits();
    EXPECT_EQ(session.accumulation().passes(), 0u);  // restarted
    EXPECT_TRUE(session.lastUpload().changed & maskOf(SceneArray::values));  // the settings re-sent
    EXPECT_EQ(session.arrays().settings.integrator, IntegratorKind::Path);
    EXPECT_EQ(session.arrays().settings.maxBounces, 5u);
    EXPECT_EQ(session.arrays().settings.lightSampling, LightSampling::Nee);
    session.renderPasses(2);  // the path integrator renders in the viewer
    EXPECT_GT(session.accumulation().passes(), 0u);
    double sum = 0;
    for (const Vec3& c : session.image()) sum += c.x + c.y + c.z;
    EXPECT_GT(sum, 0.0);
}

TEST(SettingEffects, UndoingADisplayEditOnlyRedraws) {
    EditHistory history;
    Scene scene;
    Scene before = scene;
    scene.settings.exposure = 1.0f;
    history.commit(before, "Edit scene settings", kDirtyDisplay);
    EXPECT_EQ(history.undo(scene), kDirtyDisplay);
    EXPECT_EQ(scene.settings.exposure, 0.0f);
    EXPECT_EQ(history.redo(scene), kDirtyDisplay);
    EXPECT_EQ(scene.settings.exposure, 1.0f);
    // One held gesture that also changed a rendered setting restarts on undo.
    before = scene;
    scene.settings.exposure = 2.0f;
    history.commit(before, "Edit scene settings", kDirtyDisplay, 7);
    scene.settings.maxBounces = 3;
    history.commit(before, "Edit scene settings", kDirtyScene, 7);
    EXPECT_EQ(history.undo(scene), kDirtyScene);
    EXPECT_EQ(scene.settings.exposure, 1.0f);
    EXPECT_EQ(scene.settings.maxBounces, 64);
}

}  // namespace
}  // namespace trazo
