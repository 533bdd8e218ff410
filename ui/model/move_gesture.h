// MoveGesture: moving the selected object by hand (G, or an Alt+left drag): its anchor (scene_edit.h's
// objectAnchor) follows the cursor in the plane facing the camera at the anchor's depth, the wheel moves it
// nearer or farther along the cursor's ray, and the gesture ends confirmed (one undo step: the scene as it was
// goes to the history) or cancelled (the scene as it was is put back). Host only: the cursor comes in image
// pixels of the full render size (ImagePlacement::imagePoint).
#pragma once

#include <cstdint>
#include <optional>

#include "core/vec3.h"
#include "model/image_placement.h"
#include "scene/object_id.h"
#include "scene/scene.h"

namespace trazo {

// The camera of `camera` for a width × height image, as the renderer's (integrator/camera_frame.h): the image
// point where `p` appears (none behind the camera), and the point at `depth` along the view direction under
// image point `q`.
std::optional<ImagePoint> projectToImage(const Camera& camera, uint32_t width, uint32_t height, Vec3 p);
Vec3 pointAtDepth(const Camera& camera, uint32_t width, uint32_t height, ImagePoint q, float depth);
float viewDepth(const Camera& camera, Vec3 p);  // along the view direction from the eye

class MoveGesture {
public:
    static constexpr float kDepthStep = 1.1f;  // the depth's factor per wheel notch

    // Starts moving `id` with the cursor at `cursor`; false (nothing starts) when the object is not in front of
    // the camera. Keeps the scene as it is now.
    bool begin(const Scene& scene, ObjectId id, ImagePoint cursor, uint32_t width, uint32_t height);
    bool active() const { return active_; }
    ObjectId object() const { return id_; }
    // The cursor now, and wheel notches since the last call (forward: farther): moves the object so that its
    // anchor keeps its offset from the cursor on screen. True when the scene changed.
    bool update(Scene& scene, ImagePoint cursor, float wheelNotches);
    // Ends the move and hands back the scene as it was before it (for EditHistory::commit).
    Scene confirm();
    // Ends the move, putting the scene as it was back (the camera stays as it is now).
    void cancel(Scene& scene);
    Vec3 moved() const { return applied_; }  // the anchor's displacement so far

private:
    bool active_ = false;
    ObjectId id_{};
    Scene before_;
    uint32_t width_ = 0, height_ = 0;
    ImagePoint cursor0_, anchorOnScreen0_;
    Vec3 anchor0_{0, 0, 0}, applied_{0, 0, 0};
    float depth_ = 1.0f, depth0_ = 1.0f;
};

}  // namespace trazo
