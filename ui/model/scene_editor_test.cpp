// Tests of SceneEditor's "Focus here": a click sets the camera's FocalDistance to the picked point's distance
// along the view (against a closed form), as one undo step that re-flattens; the background changes nothing.
#include "model/scene_editor.h"

#include <gtest/gtest.h>

#include <cmath>

#include "integrator/camera_frame.h"
#include "test_paths.h"

namespace trazo {
namespace {

constexpr uint32_t kWidth = 64, kHeight = 48;

// A unit sphere off the view axis at (3, 0, −2), seen from +Z; the POI (0, 0, 5) is nearer than the sphere, so
// neither |POI − POV| nor the distance to the point along the ray is the along-view distance.
Scene focusScene() {
    Scene s;
    s.settings.renderWidth = int(kWidth);
    s.settings.renderHeight = int(kHeight);
    s.settings.indirectQuality = 0;
    s.camera.pov = Vec3(0, 0, 10);
    s.camera.poi = Vec3(0, 0, 5);
    s.camera.fovDegrees = 45.0f;
    s.camera.aperture = 0.1f;
    s.spheres.push_back(Sphere{kDefaultMaterial, Vec3(3, 0, -2), 1.0f, {}});
    s.pointLights.push_back(PointLight{Vec3(0, 5, 5), Vec3(1), {}});
    return s;
}

// Where the sphere's centre is in the image (pixels from the top-left), from the renderer's camera frame.
ImagePoint centreOfSphere(const Scene& s) {
    const CameraFrame f = makeCameraFrame(s.camera.pov, s.camera.poi, s.camera.fovDegrees, kWidth, kHeight);
    const Vec3 d = s.spheres[0].center - s.camera.pov;
    const float depth = dot(d, f.forward);
    const float sx = dot(d, f.right) / depth, sy = dot(d, f.up) / depth;
    return ImagePoint{(sx / (f.tanHalfFovY * f.aspect) + 1.0f) * 0.5f * float(kWidth),
                      (1.0f - sy / f.tanHalfFovY) * 0.5f * float(kHeight)};
}

// The closed form: where the camera ray through `p` meets the sphere (in double), and that point's distance
// along normalize(POI − POV).
struct Expected {
    double alongView, alongRay;
};
Expected closedForm(const Scene& s, ImagePoint p) {
    const CameraFrame f = makeCameraFrame(s.camera.pov, s.camera.poi, s.camera.fovDegrees, kWidth, kHeight);
    const Ray ray = generateCameraRay(f, p.x, p.y);
    const Vec3 oc = ray.origin - s.spheres[0].center;
    const double b = dot(oc, ray.direction), c = double(dot(oc, oc)) - 1.0;
    const double t = -b - std::sqrt(b * b - c);
    const double point[3] = {ray.origin.x + t * ray.direction.x, ray.origin.y + t * ray.direction.y,
                             ray.origin.z + t * ray.direction.z};
    // View direction (0, 0, −1): POV and POI differ in z only.
    return Expected{s.camera.pov.z - point[2], t};
}

TEST(SceneEditorFocus, AClickFocusesAtThePickedPointsDistanceAlongTheView) {
    const Scene scene = focusScene();
    ViewerSession session(scene, createCpuBackend(2), 0);
    SceneEditor editor(session, test::tempPath("focus.scene"));
    const ImagePoint p = centreOfSphere(scene);
    const Expected want = closedForm(scene, p);
    ASSERT_NEAR(want.alongView, 11.03, 0.01);  // 12·(1 − 1/√153): the front of the sphere, along −Z

    const DirtyFlags dirty = editor.focusAt(p);
    EXPECT_EQ(dirty, kDirtyCamera | kDirtyScene);
    const float focus = session.scene().camera.focalDistance;
    EXPECT_NEAR(focus, want.alongView, 1e-4 * want.alongView);
    EXPECT_GT(std::fabs(focus - want.alongRay), 0.3);  // not the distance along the ray (11.37)
    const auto same = [](Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; };
    EXPECT_TRUE(same(session.scene().camera.pov, scene.camera.pov));  // nothing else of the camera moves
    EXPECT_TRUE(same(session.scene().camera.poi, scene.camera.poi));
    EXPECT_EQ(session.scene().camera.aperture, scene.camera.aperture);

    // One undo step, and the lens the kernels see is the new one once the edit is applied (it is fixed at
    // flatten, so a camera-only reset would keep the old focus).
    EXPECT_TRUE(editor.history().canUndo());
    EXPECT_EQ(editor.history().undoLabel(), "Focus camera");
    session.markDirty(dirty);
    session.applyEdits();
    EXPECT_EQ(session.arrays().settings.focalDistance, focus);
}

TEST(SceneEditorFocus, TheBackgroundChangesNothing) {
    const Scene scene = focusScene();
    ViewerSession session(scene, createCpuBackend(2), 0);
    SceneEditor editor(session, test::tempPath("focus_background.scene"));
    EXPECT_EQ(editor.focusAt(ImagePoint{0.5f, 0.5f}), kDirtyNone);  // the top-left corner sees nothing
    EXPECT_EQ(session.scene().camera.focalDistance, 0.0f);
    EXPECT_FALSE(editor.history().canUndo());
    EXPECT_FALSE(editor.unsaved());
}

TEST(SceneEditorFocus, UndoPutsTheFocusBackAndRedoAgain) {
    Scene scene = focusScene();
    scene.camera.focalDistance = 4.0f;  // a focus the file gave
    ViewerSession session(scene, createCpuBackend(2), 0);
    SceneEditor editor(session, test::tempPath("focus_undo.scene"));
    ASSERT_NE(editor.focusAt(centreOfSphere(scene)), kDirtyNone);
    const float focused = session.scene().camera.focalDistance;
    ASSERT_NE(focused, 4.0f);
    EXPECT_TRUE(editor.unsaved());

    const DirtyFlags undone = editor.undo();
    EXPECT_TRUE(undone & kDirtyCamera);  // the step changed the camera: undo puts it back
    EXPECT_TRUE(undone & kDirtyScene);   // and re-flattens the lens
    EXPECT_EQ(session.scene().camera.focalDistance, 4.0f);
    EXPECT_FALSE(editor.unsaved());
    session.markDirty(undone);
    session.applyEdits();
    EXPECT_EQ(session.arrays().settings.focalDistance, 4.0f);

    editor.redo();
    EXPECT_EQ(session.scene().camera.focalDistance, focused);
}

}  // namespace
}  // namespace trazo
