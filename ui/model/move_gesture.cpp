// MoveGesture: the camera's projection both ways, and the anchor kept under the cursor.
#include "model/move_gesture.h"

#include <cmath>

#include "integrator/camera_frame.h"
#include "model/scene_edit.h"

namespace trazo {
namespace {

CameraFrame frameOf(const Camera& camera, uint32_t width, uint32_t height) {
    return makeCameraFrame(camera.pov, camera.poi, camera.fovDegrees, width, height);
}

}  // namespace

std::optional<ImagePoint> projectToImage(const Camera& camera, uint32_t width, uint32_t height, Vec3 p) {
    const CameraFrame c = frameOf(camera, width, height);
    const Vec3 local = p - c.origin;
    const float z = dot(local, c.forward);
    if (!(z > 0.0f)) return std::nullopt;
    const float sx = dot(local, c.right) / z, sy = dot(local, c.up) / z;
    // generateCameraRay's sx, sy solved for x, y.
    return ImagePoint{(sx / (c.tanHalfFovY * c.aspect) + 1.0f) * 0.5f * float(width),
                      (1.0f - sy / c.tanHalfFovY) * 0.5f * float(height)};
}

Vec3 pointAtDepth(const Camera& camera, uint32_t width, uint32_t height, ImagePoint q, float depth) {
    const CameraFrame c = frameOf(camera, width, height);
    const Ray ray = generateCameraRay(c, q.x, q.y);
    return c.origin + ray.direction * (depth / dot(ray.direction, c.forward));
}

float viewDepth(const Camera& camera, Vec3 p) { return dot(p - camera.pov, normalize(camera.poi - camera.pov)); }

bool MoveGesture::begin(const Scene& scene, ObjectId id, ImagePoint cursor, uint32_t width, uint32_t height) {
    active_ = false;
    if (!isValidObject(scene, id) || width == 0 || height == 0) return false;
    const Vec3 anchor = objectAnchor(scene, id);
    const std::optional<ImagePoint> onScreen = projectToImage(scene.camera, width, height, anchor);
    if (!onScreen) return false;
    active_ = true;
    id_ = id;
    before_ = scene;
    width_ = width;
    height_ = height;
    cursor0_ = cursor;
    anchorOnScreen0_ = *onScreen;
    anchor0_ = anchor;
    applied_ = Vec3(0, 0, 0);
    depth_ = depth0_ = viewDepth(scene.camera, anchor);
    return true;
}

bool MoveGesture::update(Scene& scene, ImagePoint cursor, float wheelNotches) {
    if (!active_) return false;
    if (wheelNotches != 0) depth_ *= std::pow(kDepthStep, wheelNotches);
    // Back where it started: exactly where it was (the projection's round trip would leave a rounding step).
    if (cursor.x == cursor0_.x && cursor.y == cursor0_.y && depth_ == depth0_) {
        if (applied_.x == 0 && applied_.y == 0 && applied_.z == 0) return false;
        translateObject(scene, id_, Vec3(0, 0, 0) - applied_);
        applied_ = Vec3(0, 0, 0);
        return true;
    }
    const ImagePoint target{anchorOnScreen0_.x + cursor.x - cursor0_.x, anchorOnScreen0_.y + cursor.y - cursor0_.y};
    const Vec3 wanted = pointAtDepth(scene.camera, width_, height_, target, depth_) - anchor0_;
    const Vec3 step = wanted - applied_;
    if (step.x == 0 && step.y == 0 && step.z == 0) return false;
    translateObject(scene, id_, step);
    applied_ = wanted;
    return true;
}

Scene MoveGesture::confirm() {
    active_ = false;
    return std::move(before_);
}

void MoveGesture::cancel(Scene& scene) {
    if (!active_) return;
    active_ = false;
    const Camera camera = scene.camera;
    scene = std::move(before_);
    scene.camera = camera;
}

}  // namespace trazo
