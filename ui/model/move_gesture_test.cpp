// Tests of moving by hand: the camera's projection both ways agrees with the renderer's rays, and a move keeps
// the anchor under the cursor at its depth, the wheel moves it along the ray, cancel restores the scene exactly
// and confirm hands back the scene as it was.
#include "model/move_gesture.h"

#include <gtest/gtest.h>

#include "integrator/camera_frame.h"
#include "model/scene_edit.h"

namespace trazo {
namespace {

Scene oneSphere() {
    Scene s;
    s.camera.pov = Vec3(1, 2, 10);
    s.camera.poi = Vec3(0, 0, 0);
    s.camera.fovDegrees = 40.0f;
    s.spheres.push_back(Sphere{kDefaultMaterial, Vec3(-1, 0.5f, 0), 1.0f, {}});
    return s;
}

TEST(MoveGesture, ProjectionInvertsTheRenderersRays) {
    const Camera camera = oneSphere().camera;
    const CameraFrame frame = makeCameraFrame(camera.pov, camera.poi, camera.fovDegrees, 320, 200);
    const Ray ray = generateCameraRay(frame, 100.25f, 37.5f);
    const Vec3 p = ray.origin + ray.direction * 7.0f;
    const ImagePoint q = *projectToImage(camera, 320, 200, p);
    EXPECT_NEAR(q.x, 100.25f, 1e-3f);
    EXPECT_NEAR(q.y, 37.5f, 1e-3f);
    const Vec3 back = pointAtDepth(camera, 320, 200, q, viewDepth(camera, p));
    EXPECT_NEAR(back.x, p.x, 1e-4f);
    EXPECT_NEAR(back.y, p.y, 1e-4f);
    EXPECT_NEAR(back.z, p.z, 1e-4f);
    EXPECT_FALSE(projectToImage(camera, 320, 200, camera.pov * 2.0f - camera.poi));  // behind the eye
}

TEST(MoveGesture, TheAnchorFollowsTheCursorAtItsDepth) {
    Scene scene = oneSphere();
    const ObjectId id{ObjectId::Kind::Sphere, 0};
    const Vec3 start = scene.spheres[0].center;
    const ImagePoint onScreen = *projectToImage(scene.camera, 320, 200, start);
    MoveGesture move;
    ASSERT_TRUE(move.begin(scene, id, ImagePoint{onScreen.x + 5, onScreen.y - 3}, 320, 200));  // grabbed off-centre
    EXPECT_TRUE(move.update(scene, ImagePoint{onScreen.x + 45, onScreen.y + 17}, 0));
    const Vec3 moved = scene.spheres[0].center;
    const ImagePoint now = *projectToImage(scene.camera, 320, 200, moved);
    EXPECT_NEAR(now.x, onScreen.x + 40, 1e-2f);  // the cursor's offset kept
    EXPECT_NEAR(now.y, onScreen.y + 20, 1e-2f);
    EXPECT_NEAR(viewDepth(scene.camera, moved), viewDepth(scene.camera, start), 1e-4f);
    // The wheel: farther along the same ray, the point on screen unchanged.
    EXPECT_TRUE(move.update(scene, ImagePoint{onScreen.x + 45, onScreen.y + 17}, 2));
    const Vec3 farther = scene.spheres[0].center;
    EXPECT_NEAR(viewDepth(scene.camera, farther), viewDepth(scene.camera, start) * 1.21f, 1e-3f);
    const ImagePoint still = *projectToImage(scene.camera, 320, 200, farther);
    EXPECT_NEAR(still.x, now.x, 1e-2f);
    EXPECT_NEAR(still.y, now.y, 1e-2f);
}

TEST(MoveGesture, CancelRestoresAndConfirmHandsBackTheSceneAsItWas) {
    Scene scene = oneSphere();
    const ObjectId id{ObjectId::Kind::Sphere, 0};
    MoveGesture move;
    ASSERT_TRUE(move.begin(scene, id, ImagePoint{160, 100}, 320, 200));
    move.update(scene, ImagePoint{200, 90}, 1);
    scene.camera.pov = Vec3(0, 0, 12);  // the camera moved meanwhile: cancel keeps it
    move.cancel(scene);
    EXPECT_FALSE(move.active());
    EXPECT_EQ(scene.spheres[0].center.x, -1.0f);
    EXPECT_EQ(scene.spheres[0].center.y, 0.5f);
    EXPECT_EQ(scene.spheres[0].center.z, 0.0f);
    EXPECT_EQ(scene.camera.pov.z, 12.0f);

    ASSERT_TRUE(move.begin(scene, id, ImagePoint{160, 100}, 320, 200));
    move.update(scene, ImagePoint{200, 90}, 0);
    move.update(scene, ImagePoint{160, 100}, 0);  // back where it started: exactly there, no rounding step
    EXPECT_EQ(scene.spheres[0].center.x, -1.0f);
    EXPECT_EQ(scene.spheres[0].center.y, 0.5f);
    move.update(scene, ImagePoint{130, 120}, 0);
    const Scene before = move.confirm();
    EXPECT_EQ(before.spheres[0].center.x, -1.0f);
    EXPECT_NE(scene.spheres[0].center.x, -1.0f);
}

TEST(MoveGesture, NothingStartsBehindTheCamera) {
    Scene scene = oneSphere();
    scene.spheres[0].center = Vec3(2, 4, 20);  // behind the eye at (1, 2, 10) looking at the origin
    MoveGesture move;
    EXPECT_FALSE(move.begin(scene, {ObjectId::Kind::Sphere, 0}, ImagePoint{160, 100}, 320, 200));
    EXPECT_FALSE(move.active());
}

}  // namespace
}  // namespace trazo
