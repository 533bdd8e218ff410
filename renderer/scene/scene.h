// The host scene: what a scene file says, after validation, with names and file:line kept for messages.
// Plain C++ (STL allowed); flatten() turns it into the device arrays the kernels read.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/affine.h"
#include "core/vec3.h"
#include "scene/diagnostic.h"
#include "scene/material_fields.h"

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
// ReflectionSteps bounds the mirror chain below each camera ray, so a pass's cost grows with it. Beyond 2^16
// bounces a mirror of any reflectance below 1 − 10⁻³ has attenuated the ray by e^−65 (and the PendingRay
// bit field holds 2^27 − 1).
constexpr uint64_t kMaxReflectionSteps = 1u << 16;

struct SceneSettings {
    Vec3 backgroundColor{0, 0, 0};
    int renderWidth = 512;
    int renderHeight = 512;
    int reflectionQuality = 3;  // q -> 2·q² glossy rays
    int reflectionSteps = 1;    // maximum reflection depth
    int indirectQuality = 3;    // q -> 2·q² hemisphere rays
    float colorBleeding = 1.0f;
    int antialiasing = 1;  // 1, 4 or 16
    // Where the SceneSettings block and the parameters bounded at render time (render/strata_plan.h
    // checkRenderBounds) were written; empty when not given (a default) or not recorded.
    SourceLocation where, reflectionQualityAt, reflectionStepsAt, indirectQualityAt;
};

struct Camera {
    Vec3 pov{0, 0, 10};
    Vec3 poi{0, 0, 0};
    float fovDegrees = 45.0f;  // vertical
};

// An image decoded by FreeImage into linear float RGB (texel values as stored, no sRGB decoding).
struct TextureImage {
    int width = 0;
    int height = 0;
    std::vector<Vec3> texels;  // row 0 = bottom row of the image (uv origin bottom-left)
};

struct Texture {
    std::string name;
    std::string source;  // resolved path
    std::shared_ptr<const TextureImage> image;
    SourceLocation where;
};

constexpr int32_t kDefaultMaterial = -1;  // an object without `Material` uses the Material defaults

constexpr std::array<int32_t, kTextureSlotCount> noTextures() {
    std::array<int32_t, kTextureSlotCount> none{};
    for (int32_t& slot : none) slot = kNoTexture;
    return none;
}

// The Material block as read (scene/material_fields.h lists its parameters and their defaults).
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

// One step of an ordered transform list, kept as written (the viewer and "save scene" need it).
struct TransformStep {
    enum class Kind { Translation, Rotation, Scale } kind = Kind::Translation;
    Vec3 value{0, 0, 0};  // translation, rotation axis, or scale factors
    float angle = 0.0f;   // radians, rotations only
};

// Composes the steps in written order: later steps act on the result of earlier ones.
Affine3 composeTransforms(const std::vector<TransformStep>& steps);

struct Sphere {
    int32_t material = kDefaultMaterial;  // index into Scene::materials
    Vec3 center{0, 0, 0};
    float radius = 1.0f;
    SourceLocation where;
};

struct Box {
    int32_t material = kDefaultMaterial;
    std::vector<TransformStep> transforms;  // applied to the unit cube centred at the origin
    SourceLocation where;
};

struct Cylinder {
    int32_t material = kDefaultMaterial;
    Vec3 base{0, 0, 0};
    Vec3 axis{0, 1, 0};
    float height = 1.0f;
    float radius = 1.0f;
    SourceLocation where;
};

// A mesh as read from its OBJ file, before the Mesh block's transforms (flatten/flatten_mesh.h places it).
struct MeshData {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;        // one per position-index corner, see `corners`
    std::vector<float> uvs;           // 2 floats per uv
    struct Corner { int32_t position, normal, uv; };  // -1 = absent
    std::vector<Corner> corners;      // 3 per triangle, fan-triangulated
    bool hasNormals = false;
    bool hasUvs = false;
};

struct Mesh {
    int32_t material = kDefaultMaterial;
    std::string source;  // resolved path
    std::vector<TransformStep> transforms;
    std::shared_ptr<const MeshData> data;
    SourceLocation where;
};

// A CSG tree from a .csg file (SPEC §4). Nodes are stored in one array; the root is `root`.
struct CsgNode {
    enum class Kind { Sphere, Box, Cylinder, Union, Difference, Intersection } kind = Kind::Sphere;
    // Primitive parameters (Sphere: center/radius; Cylinder: base/axis/height/radius; Box: none).
    Vec3 center{0, 0, 0};
    float radius = 1.0f;
    Vec3 base{0, 0, 0};
    Vec3 axis{0, 1, 0};
    float height = 1.0f;
    std::vector<TransformStep> transforms;  // for operations: applied to the whole sub-tree
    int32_t left = -1, right = -1;           // node indices, operations only
    SourceLocation where;
};

struct CsgTree {
    std::vector<CsgNode> nodes;
    int32_t root = -1;
};

struct Csg {
    int32_t material = kDefaultMaterial;
    std::string source;  // resolved path
    std::vector<TransformStep> transforms;  // [ext] placement of the whole object
    std::shared_ptr<const CsgTree> tree;
    SourceLocation where;
};

struct PointLight {
    Vec3 position{0, 0, 0};
    Vec3 color{1, 1, 1};
    SourceLocation where;
};

struct AreaLight {
    Vec3 color{1, 1, 1};
    Vec3 position{0, 0, 0};  // centre
    Vec3 direction{0, -1, 0};  // normal, not necessarily unit length as written
    float rollAngle = 0.0f;    // radians
    float width = 1.0f;
    float height = 1.0f;
    int subdivisionX = 5;
    int subdivisionY = 5;
    SourceLocation where;
    SourceLocation subdivisionAt;  // the Subdivision line; empty when not recorded (then `where` is used)
};

struct Scene {
    std::string path;  // the scene file
    SceneSettings settings;
    Camera camera;
    std::vector<Texture> textures;
    std::vector<Material> materials;  // in file order
    std::vector<Sphere> spheres;
    std::vector<Box> boxes;
    std::vector<Cylinder> cylinders;
    std::vector<Mesh> meshes;
    std::vector<Csg> csgs;
    std::vector<PointLight> pointLights;
    std::vector<AreaLight> areaLights;
};

}  // namespace trazo
