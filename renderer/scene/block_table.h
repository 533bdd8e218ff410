// Block tables (host): one table per scene and CSG block (name, values, default, doc, check, setter).
// The tables drive the readers, the "did you mean" hints, and a test that compares them with SPEC.md.
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/block_lexer.h"
#include "scene/diagnostic.h"
#include "scene/scene.h"

namespace trazo {

enum class ValueKind { Real, Int, Name, Path };

// Range checks the reader applies to a parameter's values before storing them (SPEC §2).
enum class ValueCheck {
    None,
    Positive,           // every value > 0 (radius, height, size, subdivision, refraction index)
    NonNegative,        // every value >= 0 (qualities, steps, roughness, CSG indices)
    RenderSize,         // 1 … kMaxRenderSize
    Antialiasing,       // 1, 4 or 16; anything else is a warning and falls back to 1
    NonZeroVector,      // not of zero length (Direction, Axis)
    RotationAxis,       // the first three values (the axis) not of zero length
    NonZeroComponents,  // no zero component (Scale: a singular transform)
    UnitInterval,       // 0 … 1 (Opacity, ReflectionAmount)
    FieldOfView,        // strictly between 0 and 180 degrees
    ConeAngle,          // 0 … 180 degrees (ReflectionAngle is the full cone angle)
};

struct ParamInfo {
    std::string_view name;
    ValueKind kind = ValueKind::Real;
    int count = 1;                  // number of values on the line
    std::string_view defaultText;   // as SPEC.md writes it; "—" = required; "" = none
    std::string_view doc;           // one line
    ValueCheck check = ValueCheck::None;
    bool accumulates = false;       // transforms: every line adds a step instead of the later one winning
    bool required() const { return defaultText == "—"; }
};

// A parameter line whose values passed the table's kind, count, finiteness and range checks.
struct ParamValue {
    SourceLocation at;                // the line, column of the parameter name
    std::array<double, 4> numbers{};  // Real and Int values in order
    std::string text;                 // the Name or Path value
    Vec3 vec3() const { return {float(numbers[0]), float(numbers[1]), float(numbers[2])}; }
    float real() const { return float(numbers[0]); }
    int integer(int i = 0) const { return int(numbers[size_t(i)]); }
};

template <class Target>
struct ParamSpec {
    ParamInfo info;
    void (*apply)(Target&, const ParamValue&);
};

// A name given in a block (material, texture, CSG child type), resolved after the block is read.
struct NameRef {
    std::string name;  // empty when not given
    SourceLocation at;
};

struct TextureDraft {
    Texture texture;  // source as written until resolved
    SourceLocation nameAt, sourceAt;
};

enum TextureSlot { kDiffuseSlot, kSpecularSlot, kEmissiveSlot, kNormalSlot, kTextureSlotCount };

struct MaterialDraft {
    Material material;
    SourceLocation nameAt;
    std::array<NameRef, kTextureSlotCount> textures;
};

template <class T>
struct ObjectDraft {
    T object;
    NameRef material;
    SourceLocation sourceAt;  // Mesh and CSG: the Source line
};

struct CsgNodeDraft {
    CsgNode node;
    NameRef leftType, rightType;
    int leftIndex = -1, rightIndex = -1;
    SourceLocation leftIndexAt, rightIndexAt;
};

// Scene blocks (SPEC §3).
std::span<const ParamSpec<SceneSettings>> sceneSettingsTable();
std::span<const ParamSpec<Camera>> cameraTable();
std::span<const ParamSpec<TextureDraft>> textureTable();
std::span<const ParamSpec<MaterialDraft>> materialTable();
std::span<const ParamSpec<ObjectDraft<Sphere>>> sphereTable();
std::span<const ParamSpec<ObjectDraft<Box>>> boxTable();
std::span<const ParamSpec<ObjectDraft<Cylinder>>> cylinderTable();
std::span<const ParamSpec<ObjectDraft<Csg>>> csgTable();
std::span<const ParamSpec<ObjectDraft<Mesh>>> meshTable();
std::span<const ParamSpec<PointLight>> pointLightTable();
std::span<const ParamSpec<AreaLight>> areaLightTable();

// CSG-file blocks (SPEC §4); Union, Difference and Intersection share the operation table.
std::span<const ParamSpec<CsgNodeDraft>> csgSphereTable();
std::span<const ParamSpec<CsgNodeDraft>> csgBoxTable();
std::span<const ParamSpec<CsgNodeDraft>> csgCylinderTable();
std::span<const ParamSpec<CsgNodeDraft>> csgOperationTable();

struct BlockInfo {
    std::string_view name;
    std::vector<ParamInfo> params;
};

const std::vector<BlockInfo>& sceneBlocks();  // in SPEC §3 order
const std::vector<BlockInfo>& csgBlocks();    // Sphere, Box, Cylinder, Union, Difference, Intersection

// "did you mean 'X'?" for the candidate closest to `wrong` by edit distance, or "" when none is close.
std::string didYouMean(std::string_view wrong, const std::vector<std::string_view>& candidates);
std::vector<std::string_view> blockNames(const std::vector<BlockInfo>& blocks);

// The two-word spellings of SPEC §1 ("Roll" "Angle" -> "RollAngle"); "" when the pair is not one.
std::string_view twoWordSynonym(std::string_view first, std::string_view second);

// Checks one parameter line against `params`: returns its index (-1 for an unknown name, reported), with
// `valid` false when its values were rejected (reported; the parameter still counts as given).
int checkParameter(const Block& block, const std::vector<ParamInfo>& params, const ParameterLine& line,
                   ParamValue& value, bool& valid, Diagnostics& diags);
void reportMissingRequired(const Block& block, const std::vector<ParamInfo>& params,
                           const std::vector<bool>& seen, Diagnostics& diags);

// Reads every parameter line of `block` into `target` through `table`.
template <class Target>
void readParameters(const Block& block, std::span<const ParamSpec<Target>> table, Target& target,
                    Diagnostics& diags) {
    std::vector<ParamInfo> params;
    for (const ParamSpec<Target>& spec : table) params.push_back(spec.info);
    std::vector<bool> seen(params.size(), false);
    for (const ParameterLine& line : block.parameters) {
        ParamValue value;
        bool valid = false;
        const int k = checkParameter(block, params, line, value, valid, diags);
        if (k < 0) continue;
        seen[size_t(k)] = true;
        if (valid) table[size_t(k)].apply(target, value);
    }
    reportMissingRequired(block, params, seen, diags);
}

}  // namespace trazo
