// CameraController: the viewer's camera moves (orbit, pan, dolly, fly, frame, reset) as pure math on a
// Camera (POV, POI, FOV). No window, no GL: the window turns mouse and keys into these calls.
#pragma once

#include "core/aabb.h"
#include "flatten/scene_arrays.h"
#include "scene/scene.h"

namespace trazo {

// World bounds of what a flattened scene draws (its top-level BVH's root) and of its lights.
Aabb sceneBounds(const SceneArrays& arrays);

// The FocalDistance that puts `point` in focus (SPEC §6: the focus plane is perpendicular to the view): its
// distance along the view direction, dot(point − POV, normalize(POI − POV)); ≤ 0 for a point not in front.
float focalDistanceTo(const Camera& camera, Vec3 point);

struct CameraControllerSettings {
    float orbitRadiansPerPixel = 0.005f;
    float dollyFactorPerNotch = 0.85f;  // distance to the POI is multiplied by this per wheel notch forward
    float flyFractionPerSecond = 0.5f;  // WASD/QE speed: this fraction of the POV–POI distance per second
    float minDistance = 1e-3f;
    float maxPitchRadians = 1.55f;  // just short of straight up or down, where +Y stops defining "up"
};

class CameraController {
public:
    explicit CameraController(CameraControllerSettings settings = {}) : s_(settings) {}

    // Left drag: turns the POV about the POI; dx turns about +Y, dy tilts (pitch clamped), distance kept.
    void orbit(Camera& camera, float dxPixels, float dyPixels) const;
    // Middle or shift+left drag: moves POV and POI together in the image plane so that the point under the
    // cursor at the POI's depth follows the cursor. viewportHeight is the image's height in pixels on screen.
    void pan(Camera& camera, float dxPixels, float dyPixels, float viewportHeight) const;
    // Wheel: moves the POV towards (notches > 0) or away from the POI.
    void dolly(Camera& camera, float notches) const;
    // WASD/QE: forward/right/up in camera space (each -1, 0 or 1), over `seconds`; moves POV and POI together.
    void fly(Camera& camera, float forward, float right, float up, float seconds) const;
    // F: looks at the centre of `bounds` from the current direction, far enough to see all of it.
    void frame(Camera& camera, const Aabb& bounds) const;
    // R: back to the camera the file gave.
    void reset(Camera& camera, const Camera& fileCamera) const { camera = fileCamera; }

private:
    CameraControllerSettings s_;
};

}  // namespace trazo
