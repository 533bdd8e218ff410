// planRender: what each combination of the CLI's options makes of a render, before anything is allocated; and
// the long-render note it says first.
#include "render/render_plan.h"

#include <gtest/gtest.h>

#include "core/feature_mask.h"
#include "flatten/flatten.h"
#include "scene/scene_reader.h"
#include "test_paths.h"

namespace trazo {
namespace {

struct PlannedScene {
    Scene scene;
    FlattenResult flat;
};

PlannedScene load(const char* name) {
    Diagnostics diags;
    PlannedScene p{readSceneFile(test::sourcePath(std::string("scenes/") + name), diags), {}};
    EXPECT_FALSE(diags.hasErrors());
    p.flat = flatten(p.scene);
    return p;
}

TEST(RenderPlan, DefaultsAreTheScenesSizeAndOneCameraPathCycle) {
    const PlannedScene s = load("scene1_area.scene");
    const RenderPlan plan = planRender(RenderRequest{}, s.scene, s.flat.arrays);
    EXPECT_EQ(plan.width, uint32_t(s.scene.settings.renderWidth));
    EXPECT_EQ(plan.height, uint32_t(s.scene.settings.renderHeight));
    EXPECT_EQ(plan.blocks, headlessBlocks(s.flat.arrays));
    EXPECT_EQ(plan.fullCycle, fullCyclePasses(s.flat.arrays, plan.blocks));
    EXPECT_EQ(plan.range, (PassRange{0, cameraPathPasses(s.flat.arrays, plan.blocks)}));
    EXPECT_TRUE(plan.defaultPasses);
    EXPECT_FALSE(plan.openEndedPartial);
    EXPECT_EQ(plan.hostBytes, uint64_t(plan.width) * plan.height * kHostBytesPerPixel);
    EXPECT_TRUE(plan.note.empty());  // 512² of scene 1 is far from a long render
}

// SPEC §7's path tracer: one stratum of each grid a pass, and by default the fewest whole cycles of its grids
// (antialiasing cells, lens, each area light's Subdivision) that reach kPathDefaultPasses.
TEST(RenderPlan, PathScenesTakeWholeCyclesOfAtLeast64Passes) {
    PlannedScene s = load("cornell_box.scene");  // Subdivision 1 1, one antialiasing position, a pinhole
    ASSERT_EQ(s.flat.arrays.settings.integrator, IntegratorKind::Path);
    RenderPlan plan = planRender(RenderRequest{}, s.scene, s.flat.arrays);
    EXPECT_EQ(plan.blocks, StrataBlocks::ones());
    EXPECT_EQ(plan.range, (PassRange{0, kPathDefaultPasses}));
    s.flat.arrays.areaLights.at(0).cellsU = 5;
    s.flat.arrays.areaLights.at(0).cellsV = 5;  // a cycle of 25: three of them
    plan = planRender(RenderRequest{}, s.scene, s.flat.arrays);
    EXPECT_EQ(plan.fullCycle, 25u);
    EXPECT_EQ(plan.range, (PassRange{0, 75}));
}

TEST(RenderPlan, SizeBlocksAndPassesAsAsked) {
    const PlannedScene s = load("scene1_area.scene");
    RenderRequest r;
    r.width = 30;
    r.height = 20;
    r.blocks = StrataBlocks::ones();
    r.spp = 7;
    RenderPlan plan = planRender(r, s.scene, s.flat.arrays);
    EXPECT_EQ(plan.pixels(), 600u);
    EXPECT_EQ(plan.blocks, StrataBlocks::ones());
    EXPECT_EQ(plan.fullCycle, 100u);  // the 10 × 10 light, one cell a pass
    EXPECT_EQ(plan.range, (PassRange{0, 7}));
    EXPECT_FALSE(plan.defaultPasses);
    r.passes = PassRange{5, 9};  // --passes wins over --spp
    plan = planRender(r, s.scene, s.flat.arrays);
    EXPECT_EQ(plan.range, (PassRange{5, 9}));
    const RenderLimits limits = plan.limits(r, true);
    EXPECT_EQ(limits.passes, 4u);
    EXPECT_EQ(limits.firstPass, 5u);
    EXPECT_EQ(limits.cyclePasses, 100u);
    EXPECT_TRUE(limits.errorProbe);
}

TEST(RenderPlan, ATimeOrTargetErrorLeavesThePassesOpen) {
    const PlannedScene s = load("scene1_area.scene");
    for (bool byTime : {true, false}) {
        RenderRequest r;
        (byTime ? r.seconds : r.targetError) = 0.5;
        RenderPlan plan = planRender(r, s.scene, s.flat.arrays);
        EXPECT_EQ(plan.range, (PassRange{0, kMaxProgressivePasses}));
        EXPECT_FALSE(plan.openEndedPartial);
        r.partial = true;
        plan = planRender(r, s.scene, s.flat.arrays);
        EXPECT_TRUE(plan.openEndedPartial);
        EXPECT_FALSE(plan.limits(r, true).errorProbe) << "a partial's parts are merged: no probe";
        r.spp = 4;  // a partial of asked passes is not open-ended
        EXPECT_FALSE(planRender(r, s.scene, s.flat.arrays).openEndedPartial);
    }
}

TEST(RenderPlan, ALongRenderIsAnnouncedUnlessATimeBoundsIt) {
    const PlannedScene s = load("scene1_area.scene");
    RenderRequest r;
    r.width = r.height = 16384;
    r.spp = 100000;
    EXPECT_NE(planRender(r, s.scene, s.flat.arrays).note, "");
    r.seconds = 10;
    EXPECT_EQ(planRender(r, s.scene, s.flat.arrays).note, "");
}

TEST(RenderPlan, TargetErrorNeedsAProbeOrHalves) {
    RenderLimits limits;
    limits.targetError = 0.01;
    limits.cyclePasses = kMaxCyclePasses;  // the cycle was cut: no halves
    EXPECT_NE(targetErrorProblem(limits), "");
    limits.errorProbe = true;
    EXPECT_EQ(targetErrorProblem(limits), "");
    limits.errorProbe = false;
    limits.cyclePasses = 100;
    EXPECT_EQ(targetErrorProblem(limits), "");
    limits.targetError = 0;
    limits.cyclePasses = kMaxCyclePasses;
    EXPECT_EQ(targetErrorProblem(limits), "");
    limits.targetError = 0.01;
    limits.noiseless = true;  // the error is 0: nothing to estimate
    EXPECT_EQ(targetErrorProblem(limits), "");
}

// Only the point-light-only variant at one centred position through a pinhole draws nothing: any of area
// lights, indirect light, a glossy or mirror reflection, transparency, antialiasing or a lens makes noise (or
// may), and such a render keeps its probe.
TEST(RenderPlan, OnlyRendersThatDrawNothingAreNoiseless) {
    PlannedScene s = load("scene1_point.scene");
    RenderPlan plan = planRender(RenderRequest{}, s.scene, s.flat.arrays);
    EXPECT_TRUE(plan.noiseless);
    RenderLimits limits = plan.limits(RenderRequest{}, true);
    EXPECT_TRUE(limits.noiseless);
    EXPECT_FALSE(limits.errorProbe);
    for (const char* name : {"scene1_area.scene", "scene9_indirect_point.scene", "scene4_reflect.scene",
                             "scene6_glossy.scene", "scene7_refract.scene", "effect_depth_of_field.scene"}) {
        const PlannedScene other = load(name);
        const RenderPlan p = planRender(RenderRequest{}, other.scene, other.flat.arrays);
        EXPECT_FALSE(p.noiseless) << name;
        EXPECT_TRUE(p.limits(RenderRequest{}, true).errorProbe) << name;
    }
    s.flat.arrays.settings.antialiasing = 4;
    EXPECT_FALSE(noSamplingNoise(s.flat.arrays));
    s.flat.arrays.settings.antialiasing = 1;
    s.flat.arrays.settings.aperture = 0.1f;
    EXPECT_FALSE(noSamplingNoise(s.flat.arrays));
    s.flat.arrays.settings.aperture = 0.0f;
    EXPECT_TRUE(noSamplingNoise(s.flat.arrays));
}

TEST(LongRenderNote, OnlyForALongRenderAndSaysItsCost) {
    SceneArrays a;
    a.settings = RenderSettings{};
    a.settings.antialiasing = 1;
    a.settings.reflectionSteps = 1;
    a.settings.indirectQuality = 3;
    a.features = kFeatureIndirect;
    a.pointLights.push_back(PointLightData{});
    const StrataBlocks b = StrataBlocks::ones();
    EXPECT_EQ(raysPerPixelPass(a, b), 1.0 + 1.0 + 1.0 * (1.0 + 1.0));  // camera, shadow, one direction and its Q
    EXPECT_TRUE(longRenderNote(a, b, 18, true, 512, 512).empty());
    a.settings.indirectQuality = 724;  // 1048352 directions in one pass
    const StrataBlocks whole = clampToScene(a, StrataBlocks::whole());
    const std::string note = longRenderNote(a, whole, 1, true, 512, 512);
    EXPECT_NE(note.find("1 pass (the default: one full cycle"), std::string::npos) << note;
    EXPECT_NE(note.find("512×512"), std::string::npos) << note;
    EXPECT_NE(longRenderNote(a, b, kMaxCyclePasses, true, 4096, 4096).find("cut at 65536"), std::string::npos);
}

}  // namespace
}  // namespace trazo
