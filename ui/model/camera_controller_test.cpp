// Tests of the camera controller's moves (pure math, no window): orbit keeps the distance and the POI, pan
// moves both points, dolly scales the distance, fly, frame and reset.
#include "model/camera_controller.h"

#include <gtest/gtest.h>

#include <cmath>

#include "flatten/flatten.h"
#include "integrator/camera_frame.h"

namespace trazo {
namespace {

Camera fileCamera() {
    Camera c;
    c.pov = {0, 5, 15};
    c.poi = {0, 5, 0};
    c.fovDegrees = 45;
    return c;
}

void expectNear(Vec3 a, Vec3 b, float tolerance = 1e-4f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(CameraController, OrbitKeepsPoiAndDistance) {
    const CameraController controller;
    Camera c = fileCamera();
    controller.orbit(c, 120.0f, -45.0f);
    expectNear(c.poi, Vec3(0, 5, 0));
    EXPECT_NEAR(length(c.pov - c.poi), 15.0f, 1e-3f);
    EXPECT_GT(std::fabs(c.pov.x), 1.0f);  // turned about +Y
    EXPECT_LT(c.pov.y, 5.0f);             // dragging up tilts the camera down
}

TEST(CameraController, HorizontalOrbitTurnsAboutY) {
    CameraControllerSettings s;
    s.orbitRadiansPerPixel = 0.01f;
    const CameraController controller(s);
    Camera c = fileCamera();
    controller.orbit(c, -157.07963f, 0.0f);  // a quarter turn
    expectNear(c.pov, Vec3(15, 5, 0), 1e-3f);
}

TEST(CameraController, OrbitPitchStopsShortOfThePole) {
    const CameraController controller;
    Camera c = fileCamera();
    controller.orbit(c, 0.0f, 1e6f);
    const Vec3 offset = normalize(c.pov - c.poi);
    EXPECT_LT(offset.y, 1.0f);
    EXPECT_GT(offset.y, 0.99f);
    const CameraFrame f = makeCameraFrame(c.pov, c.poi, c.fovDegrees, 4, 4);  // still a valid frame
    EXPECT_TRUE(std::isfinite(f.right.x) && std::isfinite(f.up.y));
}

TEST(CameraController, PanMovesPovAndPoiTogetherInTheImagePlane) {
    const CameraController controller;
    Camera c = fileCamera();
    // At the POI's depth the image is 2·15·tan(22.5°) units tall; 100 of 200 pixels is half of that.
    controller.pan(c, 100.0f, 0.0f, 200.0f);
    const float half = 15.0f * std::tan(22.5f * 3.14159265f / 180.0f);
    expectNear(c.poi, Vec3(-half, 5, 0), 1e-3f);  // drag right: the scene follows the cursor, camera goes left
    expectNear(c.pov - c.poi, Vec3(0, 0, 15), 1e-4f);
    controller.pan(c, 0.0f, 100.0f, 200.0f);
    EXPECT_NEAR(c.poi.y, 5.0f + half, 1e-3f);
}

TEST(CameraController, DollyScalesTheDistanceAndNeverCrossesThePoi) {
    const CameraController controller;
    Camera c = fileCamera();
    controller.dolly(c, 1.0f);
    EXPECT_NEAR(length(c.pov - c.poi), 15.0f * 0.85f, 1e-4f);
    controller.dolly(c, -1.0f);
    EXPECT_NEAR(length(c.pov - c.poi), 15.0f, 1e-4f);
    controller.dolly(c, 1000.0f);
    EXPECT_GT(c.pov.z, c.poi.z);  // still in front
    expectNear(c.poi, Vec3(0, 5, 0));
}

TEST(CameraController, FlyMovesAlongTheView) {
    const CameraController controller;
    Camera c = fileCamera();
    controller.fly(c, 1.0f, 0.0f, 0.0f, 1.0f);  // half the distance per second, forward = -Z here
    expectNear(c.pov, Vec3(0, 5, 7.5f));
    expectNear(c.poi, Vec3(0, 5, -7.5f));
    controller.fly(c, 0.0f, 1.0f, 1.0f, 0.1f);
    EXPECT_GT(c.pov.x, 0.0f);
    EXPECT_GT(c.pov.y, 5.0f);
}

TEST(CameraController, FrameLooksAtTheBoundsFromTheSameDirection) {
    const CameraController controller;
    Camera c = fileCamera();
    Aabb b;
    b.grow(Vec3(-1, -1, -1));
    b.grow(Vec3(3, 1, 1));
    controller.frame(c, b);
    expectNear(c.poi, Vec3(1, 0, 0));
    expectNear(normalize(c.pov - c.poi), Vec3(0, 0, 1));
    const float radius = 0.5f * length(Vec3(4, 2, 2));
    EXPECT_NEAR(length(c.pov - c.poi), radius / std::sin(22.5f * 3.14159265f / 180.0f), 1e-3f);
}

TEST(CameraController, ResetRestoresTheFileCamera) {
    const CameraController controller;
    Camera c = fileCamera();
    controller.orbit(c, 10, 10);
    controller.dolly(c, 2);
    c.fovDegrees = 80;
    controller.reset(c, fileCamera());
    expectNear(c.pov, fileCamera().pov, 0.0f);
    expectNear(c.poi, fileCamera().poi, 0.0f);
    EXPECT_EQ(c.fovDegrees, 45.0f);
}

TEST(CameraController, SceneBoundsCoverShapesAndLights) {
    Scene scene;
    scene.spheres.push_back({kDefaultMaterial, {0, 1, 0}, 1.0f, {}});
    Box box;
    box.transforms = {{TransformStep::Kind::Scale, {10, 1, 10}, 0}, {TransformStep::Kind::Translation, {0, -0.5f, 0}, 0}};
    scene.boxes.push_back(box);
    PointLight light;
    light.position = {0, 9, 0};
    scene.pointLights.push_back(light);
    // The objects' bounds come padded (Aabb::padded) into the top-level BVH.
    const Aabb b = sceneBounds(flatten(scene).arrays);
    expectNear(b.min, Vec3(-5, -1, -5), 2e-3f);
    expectNear(b.max, Vec3(5, 9, 5), 2e-3f);
    EXPECT_TRUE(sceneBounds(flatten(Scene{}).arrays).empty());
}

}  // namespace
}  // namespace trazo
