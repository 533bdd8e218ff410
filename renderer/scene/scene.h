// The host scene: what a scene file says, after validation, with names and file:line kept for messages.
// Plain C++ (STL allowed); flatten() turns it into the device arrays the kernels read.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/render_settings.h"
#include "core/vec3.h"
#include "core/view_transform.h"
#include "objects/object_kind_list.h"
#include "scene/diagnostic.h"
#include "scene/kinds/light_kind_model.h"
#include "scene/kinds/object_kind_model.h"
#include "scene/object_basics.h"
#include "shading/material_fields.h"

namespace trazo {

// The most pixels an image may have on a side (RenderWidth, RenderHeight, --width, --height, the viewer).
constexpr int kMaxRenderSize = 16384;

// The bounds of the settings that size a render's work (checkRenderBounds, render/strata_plan.h). A stratified
// grid (an area light's Subdivision nx·ny cells, the 2·q² strata of ReflectionQuality or IndirectQuality) holds
// at most kMaxGridStrata strata: its counts, products and stratum indices then stay far inside the kernels'
// 32-bit arithmetic (2^32 wraps to 0 and divided by zero) and exact in float (cell index + jitter), and one
// full cycle of such a grid is already 2^20 samples a pixel.
constexpr uint64_t kMaxGridStrata = 1u << 20;
constexpr int kMaxStrataQuality = 724;  // the largest q with 2·q² ≤ kMaxGridStrata
constexpr int kMaxGridSide = 1024;      // the largest square grid: 1024 × 1024 = kMaxGridStrata
static_assert(2ull * kMaxStrataQuality * kMaxStrataQuality <= kMaxGridStrata &&
              2ull * (kMaxStrataQuality + 1) * (kMaxStrataQuality + 1) > kMaxGridStrata);
static_assert(uint64_t(kMaxGridSide) * kMaxGridSide == kMaxGridStrata);
// SPEC §7's MaxBounces: a path of albedo 1 (a mirror enclosure) is never ended by Russian roulette, so its cost
// grows with the bound. 4096 bounces of any albedo below 0.998 have carried its light below e^-8.
constexpr int kMaxBounces = 4096;
// ReflectionSteps bounds the mirror chain below each camera ray, so a pass's cost grows with it. Beyond 2^16
// bounces a mirror of any reflectance below 1 − 10⁻³ has attenuated the ray by e^−65 (and the PendingRay
// bit field holds 2^27 − 1).
constexpr uint64_t kMaxReflectionSteps = 1u << 16;

// An image decoded by FreeImage into linear float RGB (texel values as stored, no sRGB decoding).
struct TextureImage {
    int width = 0;
    int height = 0;
    std::vector<Vec3> texels;  // row 0 = bottom row of the image (uv origin bottom-left)
    bool eightBit = false;     // 8-bit channels (k/255): decoded from sRGB as a colour texture under path (SPEC §7)
};

struct SceneSettings {
    Vec3 backgroundColor{0, 0, 0};
    int renderWidth = 512;
    int renderHeight = 512;
    int reflectionQuality = 3;  // q -> 2·q² glossy rays
    int reflectionSteps = 1;    // maximum reflection depth
    int indirectQuality = 3;    // q -> 2·q² hemisphere rays
    float colorBleeding = 1.0f;
    int antialiasing = 1;  // 1, 4 or 16
    // SPEC §7: the integrator, its bounce limit and estimator, the environment and the image transform.
    IntegratorKind integrator = IntegratorKind::Thesis;
    int maxBounces = 64;
    LightSampling lightSampling = LightSampling::Mis;
    std::string environmentMap;  // resolved path; empty: none
    std::shared_ptr<const TextureImage> environmentImage;
    float environmentRotation = 0.0f;  // degrees about +Y
    float exposure = 0.0f;             // stops
    ViewTransform viewTransform = ViewTransform::Auto;
    // Where the SceneSettings block and the parameters bounded at render time (render/strata_plan.h
    // checkRenderBounds) were written; empty when not given (a default) or not recorded.
    SourceLocation where, reflectionQualityAt, reflectionStepsAt, indirectQualityAt, environmentMapAt;
};

struct Camera {
    Vec3 pov{0, 0, 10};
    Vec3 poi{0, 0, 0};
    float fovDegrees = 45.0f;  // vertical
    // Depth of field (SPEC §6): the lens's radius (0: the pinhole of §5), the distance in focus (0: |POI − POV|),
    // and q of its q rings × 2q sectors of strata.
    float aperture = 0.0f;
    float focalDistance = 0.0f;
    int lensQuality = 3;
    SourceLocation lensQualityAt;  // bounded at render time (checkRenderBounds)
};

struct Texture {
    std::string name;
    std::string source;  // resolved path
    std::shared_ptr<const TextureImage> image;
    SourceLocation where;
};

constexpr std::array<int32_t, kTextureSlotCount> noTextures() {
    std::array<int32_t, kTextureSlotCount> none{};
    for (int32_t& slot : none) slot = kNoTexture;
    return none;
}

// The Material block as read (shading/material_fields.h lists its parameters and their defaults).
struct Material {
    std::string name;
#define TRAZO_X(Type, name, fallback, ...) Type name = fallback;
#define TRAZO_NO_SLOTS()
    TRAZO_MATERIAL_FIELDS(TRAZO_X, TRAZO_NO_SLOTS)
#undef TRAZO_NO_SLOTS
#undef TRAZO_X
    std::array<int32_t, kTextureSlotCount> textures = noTextures();  // by TextureSlot; into Scene::textures
    SourceLocation where;

    bool usesTextures() const {
        for (int32_t t : textures)
            if (t != kNoTexture) return true;
        return false;
    }
};

struct Scene {
    std::string path;  // the scene file
    SceneSettings settings;
    Camera camera;
    std::vector<Texture> textures;
    std::vector<Material> materials;  // in file order
#define TRAZO_X(Shape, array, Kind, keyword) std::vector<Kind> array;
    TRAZO_OBJECT_KINDS(TRAZO_X)  // spheres, boxes, ...: scene/kinds/<kind>.h
#undef TRAZO_X
#define TRAZO_X(Data, array, Kind, ...) std::vector<Kind> array;
    TRAZO_LIGHT_KINDS(TRAZO_X)  // pointLights, areaLights: scene/kinds/<kind>.h
#undef TRAZO_X
};

}  // namespace trazo
