// Block tables (host): the parameters of every block as SPEC.md §3–§4 lists them. Defaults are not written
// here: withDefaults reads them from scene.h's initialisers.
#include "scene/block_table.h"

namespace trazo {
namespace {

using Check = ValueCheck;
using Step = TransformStep::Kind;

template <class Row>
std::vector<Row> concat(std::initializer_list<std::vector<Row>> parts) {
    std::vector<Row> all;
    for (const std::vector<Row>& part : parts) all.insert(all.end(), part.begin(), part.end());
    return all;
}

// One transform row: every line appends a step of `kind` to `Holder::transforms`, in written order.
template <class Holder>
ParamSpec<Holder> transformRow(ParamInfo info, Step kind) {
    info.kind = ValueKind::Real;
    info.accumulates = true;
    return {info,
            [kind](Holder& h, const ParamValue& v) {
                h.transforms.push_back({kind, v.vec3(), kind == Step::Rotation ? v.real(3) : 0.0f});
            },
            [kind](const Holder& h, std::vector<ParamValue>& out) {
                for (size_t i = 0; i < h.transforms.size(); ++i) {
                    const TransformStep& t = h.transforms[i];
                    if (t.kind != kind) continue;
                    ParamValue v;
                    v.numbers = {t.value.x, t.value.y, t.value.z, t.angle};
                    v.step = i;
                    out.push_back(v);
                }
            }};
}

// Box, CSG and Mesh objects and every CSG-file node (any struct with `transforms`).
template <class Holder>
std::vector<ParamSpec<Holder>> transformRows() {
    return {
        transformRow<Holder>({.name = "Translation", .count = 3, .doc = "translate by x y z (in written order)"},
                             Step::Translation),
        transformRow<Holder>({.name = "Rotation",
                              .count = 4,
                              .doc = "rotate about axis x y z by an angle in radians",
                              .check = Check::RotationAxis},
                             Step::Rotation),
        transformRow<Holder>(
            {.name = "Scale", .count = 3, .doc = "scale by sx sy sz about the origin", .check = Check::NonZeroComponents},
            Step::Scale),
    };
}

// Scene Sphere objects and CSG Sphere nodes (Sphere or CsgNode).
template <class Shape>
std::vector<ParamSpec<Shape>> sphereRows() {
    return {
        field("Center", &Shape::center, "centre"),
        field("Radius", &Shape::radius, "radius", Check::Radius),
    };
}

// Scene Cylinder objects and CSG Cylinder nodes (Cylinder or CsgNode).
template <class Shape>
std::vector<ParamSpec<Shape>> cylinderRows() {
    return {
        field("Base", &Shape::base, "centre of the bottom cap"),
        field("Axis", &Shape::axis, "direction from the bottom cap to the top", Check::NonZeroVector),
        field("Height", &Shape::height, "length along the axis", Check::Positive),
        field("Radius", &Shape::radius, "radius", Check::Radius),
    };
}

// A Name or Path row over the string `text(target)` and the location its line is remembered at.
template <class Target, class Text>
ParamSpec<Target> textRow(ParamInfo info, Text text, SourceLocation Target::*at) {
    return {info,
            [text, at](Target& t, const ParamValue& v) {
                text(t) = v.text;
                t.*at = v.at;
            },
            [text, at](const Target& t, std::vector<ParamValue>& out) {
                if (text(t).empty()) return;
                ParamValue v;
                v.text = text(t);
                v.at = t.*at;
                out.push_back(v);
            }};
}

// A name another block declares (a material, a texture, a CSG child type), kept as written for the reader.
template <class Target, class Ref>
ParamSpec<Target> nameRefRow(ParamInfo info, Ref ref) {
    info.kind = ValueKind::Name;
    return {info, [ref](Target& t, const ParamValue& v) { ref(t) = {v.text, v.at}; },
            [ref](const Target& t, std::vector<ParamValue>& out) {
                if (ref(t).name.empty()) return;
                ParamValue v;
                v.text = ref(t).name;
                v.at = ref(t).at;
                out.push_back(v);
            }};
}

template <class Object>
ParamSpec<ObjectDraft<Object>> materialRow() {
    return nameRefRow<ObjectDraft<Object>>({.name = "Material", .doc = "material name (the Material defaults, with a warning)"},
                                      [](auto& d) -> auto& { return d.material; });
}

template <class Object>
ParamSpec<ObjectDraft<Object>> sourceRow(std::string_view doc) {
    return textRow<ObjectDraft<Object>>({.name = "Source", .kind = ValueKind::Path, .required = true, .doc = doc},
                                   [](auto& d) -> auto& { return d.object.source; },
                                   &ObjectDraft<Object>::sourceAt);
}

// Each object kind's own rows, and for a kind read from a file what its Source names.
template <class Object>
std::vector<ParamSpec<Object>> ownRows();
template <>
std::vector<ParamSpec<Sphere>> ownRows() { return sphereRows<Sphere>(); }
template <>
std::vector<ParamSpec<Box>> ownRows() { return transformRows<Box>(); }
template <>
std::vector<ParamSpec<Cylinder>> ownRows() { return cylinderRows<Cylinder>(); }
template <>
std::vector<ParamSpec<Csg>> ownRows() { return transformRows<Csg>(); }
template <>
std::vector<ParamSpec<Mesh>> ownRows() { return transformRows<Mesh>(); }
template <class Object>
constexpr std::string_view kSourceDoc = "";
template <>
constexpr std::string_view kSourceDoc<Csg> = ".csg file with the tree";
template <>
constexpr std::string_view kSourceDoc<Mesh> = ".obj file";

// An object block's rows: Material, Source for a kind read from a file, then the kind's own.
template <class Object>
std::vector<ParamSpec<ObjectDraft<Object>>> objectRows() {
    std::vector<ParamSpec<ObjectDraft<Object>>> named{materialRow<Object>()};
    if constexpr (Object::kReadFromFile) named.push_back(sourceRow<Object>(kSourceDoc<Object>));
    return withDefaults(
        concat<ParamSpec<ObjectDraft<Object>>>({named, lift(&ObjectDraft<Object>::object, ownRows<Object>())}));
}

// A Name row whose value is one of `words`, stored as an enumerator: word i is Enum(first + i); a value below
// `first` (a default that depends on other settings) is written as nothing.
template <class Target, class Enum>
ParamSpec<Target> choice(std::string_view name, Enum Target::*member, std::span<const std::string_view> words,
                         std::string_view doc, uint32_t first = 0) {
    const ParamInfo info{.name = name, .kind = ValueKind::Name, .doc = doc, .choices = words};
    return {info,
            [member, words, first](Target& t, const ParamValue& v) {
                for (size_t i = 0; i < words.size(); ++i)
                    if (words[i] == v.text) t.*member = Enum(first + uint32_t(i));
            },
            [member, words, first](const Target& t, std::vector<ParamValue>& out) {
                const uint32_t value = uint32_t(t.*member);
                if (value < first || value - first >= words.size()) return;
                ParamValue v;
                v.text = std::string(words[value - first]);
                out.push_back(v);
            }};
}

constexpr std::string_view kIntegratorWords[] = {
#define TRAZO_X(kind, type, keyword) keyword,
    TRAZO_INTEGRATORS(TRAZO_X)
#undef TRAZO_X
};
constexpr std::string_view kLightSamplingWords[] = {"mis", "nee", "bsdf"};
constexpr std::string_view kViewTransformWords[] = {"linear", "srgb"};  // after ViewTransform::Auto

template <class Target>
BlockInfo infoOf(std::string_view name, std::span<const ParamSpec<Target>> table) {
    BlockInfo b{name, {}};
    for (const ParamSpec<Target>& spec : table) b.params.push_back(spec.info);
    return b;
}

}  // namespace

const std::array<TextureSlotInfo, kTextureSlotCount>& textureSlots() {
    static const std::array<TextureSlotInfo, kTextureSlotCount> slots = {{
#define TRAZO_X(slot, keyword, doc) {keyword, doc},
        TRAZO_TEXTURE_SLOTS(TRAZO_X)
#undef TRAZO_X
    }};
    return slots;
}

MaterialDraft materialDraft(const Material& material, const std::vector<Texture>& textures) {
    MaterialDraft d{material, {}, {}};
    for (size_t s = 0; s < kTextureSlotCount; ++s) {
        const int32_t index = material.textures[s];
        if (index >= 0 && size_t(index) < textures.size()) d.textures[s].name = textures[size_t(index)].name;
    }
    return d;
}

std::span<const ParamSpec<SceneSettings>> sceneSettingsTable() {
    static const std::vector<ParamSpec<SceneSettings>> rows = withDefaults<SceneSettings>({
        colour("BackgroundColor", &SceneSettings::backgroundColor, "colour of rays that hit nothing"),
        field("RenderWidth", &SceneSettings::renderWidth, "image width in pixels", Check::RenderSize),
        field("RenderHeight", &SceneSettings::renderHeight, "image height in pixels", Check::RenderSize),
        field("ReflectionQuality", &SceneSettings::reflectionQuality, "q: 2·q² glossy reflection rays", Check::StrataQuality,
              ValueUnit::None, &SceneSettings::reflectionQualityAt),
        field("ReflectionSteps", &SceneSettings::reflectionSteps, "maximum reflection depth", Check::ReflectionDepth,
              ValueUnit::None, &SceneSettings::reflectionStepsAt),
        field("IndirectQuality", &SceneSettings::indirectQuality, "q: 2·q² hemisphere rays for indirect light",
              Check::StrataQuality, ValueUnit::None, &SceneSettings::indirectQualityAt),
        field("ColorBleeding", &SceneSettings::colorBleeding, "factor on the indirect light"),
        field("Antialiasing", &SceneSettings::antialiasing, "samples per pixel: 1, 4 or 16", Check::Antialiasing),
        choice("Integrator", &SceneSettings::integrator, kIntegratorWords,
               "thesis: the thesis's model (SPEC §5); path: light transport (SPEC §7)"),
        field("MaxBounces", &SceneSettings::maxBounces, "path: scatterings after the first a path may take",
              Check::BounceCount),
        choice("LightSampling", &SceneSettings::lightSampling, kLightSamplingWords,
               "path: light by mis (both, weighted), nee (light samples) or bsdf (scattered rays)"),
        textRow<SceneSettings>({.name = "EnvironmentMap", .kind = ValueKind::Path, .doc = "equirectangular image of the sky's radiance"},
                               [](auto& s) -> auto& { return s.environmentMap; }, &SceneSettings::environmentMapAt),
        field("EnvironmentRotation", &SceneSettings::environmentRotation, "turn of the environment about +Y",
              Check::None, ValueUnit::Degrees),
        field("Exposure", &SceneSettings::exposure, "stops: the image is 2^Exposure × the pixel", Check::Stops),
        choice("ViewTransform", &SceneSettings::viewTransform, kViewTransformWords,
               "8-bit files and the viewer: linear or srgb", uint32_t(ViewTransform::Linear)),
    });
    return rows;
}

std::span<const ParamSpec<Camera>> cameraTable() {
    static const std::vector<ParamSpec<Camera>> rows = withDefaults<Camera>({
        field("POV", &Camera::pov, "camera position"),
        field("POI", &Camera::poi, "point looked at"),
        field("FOV", &Camera::fovDegrees, "vertical field of view in degrees", Check::FieldOfView, ValueUnit::Degrees),
        field("Aperture", &Camera::aperture, "lens radius for depth of field; 0 = pinhole", Check::NonNegative),
        field("FocalDistance", &Camera::focalDistance, "distance in focus; 0 = the distance to POI", Check::NonNegative),
        field("LensQuality", &Camera::lensQuality, "q: q rings × 2q sectors of lens strata", Check::StrataQuality,
              ValueUnit::None, &Camera::lensQualityAt),
    });
    return rows;
}

std::span<const ParamSpec<TextureDraft>> textureTable() {
    static const std::vector<ParamSpec<TextureDraft>> rows = withDefaults<TextureDraft>({
        textRow<TextureDraft>({.name = "Name", .kind = ValueKind::Name, .required = true, .doc = "name materials use to refer to it"},
                   [](auto& t) -> auto& { return t.texture.name; }, &TextureDraft::nameAt),
        textRow<TextureDraft>({.name = "Source", .kind = ValueKind::Path, .required = true, .doc = "image file, any format FreeImage reads"},
                   [](auto& t) -> auto& { return t.texture.source; }, &TextureDraft::sourceAt),
    });
    return rows;
}

namespace {

// The Material's rows: shading/material_fields.h's list, with the texture slots where the list places them.
std::vector<ParamSpec<MaterialDraft>> materialRows() {
    std::vector<ParamSpec<MaterialDraft>> rows;
    auto add = [&](const ParamSpec<Material>& row) {
        rows.push_back(lift<MaterialDraft, Material>(&MaterialDraft::material, {row}).front());
    };
#define TRAZO_X(HostType, name, fallback, Type, kernelName, toKernel, keyword, check, unit, doc) \
    add(field(keyword, &Material::name, doc, Check::check, ValueUnit::unit));
#define TRAZO_SLOTS()                                                                                       \
    for (size_t s = 0; s < kTextureSlotCount; ++s)                                                          \
        rows.push_back(nameRefRow<MaterialDraft>({.name = textureSlots()[s].name, .doc = textureSlots()[s].doc}, \
                                                 [s](auto& d) -> auto& { return d.textures[s]; }));
    TRAZO_MATERIAL_FIELDS(TRAZO_X, TRAZO_SLOTS)
#undef TRAZO_SLOTS
#undef TRAZO_X
    return rows;
}

}  // namespace

std::span<const ParamSpec<MaterialDraft>> materialTable() {
    static const std::vector<ParamSpec<MaterialDraft>> rows = withDefaults(concat<ParamSpec<MaterialDraft>>({
        {textRow<MaterialDraft>({.name = "Name", .kind = ValueKind::Name, .required = true, .doc = "name objects use to refer to it"},
                    [](auto& m) -> auto& { return m.material.name; }, &MaterialDraft::nameAt)},
        materialRows(),
    }));
    return rows;
}

#define TRAZO_X(Shape, array, Kind, keyword)                                              \
    template <>                                                                           \
    std::span<const ParamSpec<ObjectDraft<Kind>>> objectTable<Kind>() {                   \
        static const std::vector<ParamSpec<ObjectDraft<Kind>>> rows = objectRows<Kind>(); \
        return rows;                                                                      \
    }
TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X

template <>
std::span<const ParamSpec<PointLight>> lightTable<PointLight>() {
    static const std::vector<ParamSpec<PointLight>> rows = withDefaults<PointLight>({
        field("Position", &PointLight::position, "position", Check::LightPosition),
        colour("Color", &PointLight::color, "colour and intensity (no falloff)"),
    });
    return rows;
}

template <>
std::span<const ParamSpec<AreaLight>> lightTable<AreaLight>() {
    static const std::vector<ParamSpec<AreaLight>> rows = withDefaults<AreaLight>({
        colour("Color", &AreaLight::color, "colour and intensity (no falloff)"),
        field("Position", &AreaLight::position, "centre of the rectangle", Check::LightPosition),
        field("Direction", &AreaLight::direction, "normal of the rectangle", Check::NonZeroVector),
        field("RollAngle", &AreaLight::rollAngle, "turn of the rectangle about its normal, radians", Check::None,
              ValueUnit::Radians),
        field("Width", &AreaLight::width, "size along u", Check::Positive),
        field("Height", &AreaLight::height, "size along v", Check::Positive),
        {{.name = "Subdivision",
          .kind = ValueKind::Int,
          .count = 2,
          .doc = "strata across the width and the height",
          .check = Check::GridCells},
         [](AreaLight& l, const ParamValue& v) {
             l.subdivisionX = v.integer(0);
             l.subdivisionY = v.integer(1);
             l.subdivisionAt = v.at;
         },
         [](const AreaLight& l, std::vector<ParamValue>& out) {
             ParamValue v;
             v.numbers = {double(l.subdivisionX), double(l.subdivisionY), 0, 0};
             v.at = l.subdivisionAt;
             out.push_back(v);
         }},
    });
    return rows;
}

std::span<const ParamSpec<CsgNodeDraft>> csgSphereTable() {
    static const std::vector<ParamSpec<CsgNodeDraft>> rows = withDefaults(
        concat<ParamSpec<CsgNodeDraft>>({lift(&CsgNodeDraft::node, sphereRows<CsgNode>()), lift(&CsgNodeDraft::node, transformRows<CsgNode>())}));
    return rows;
}

std::span<const ParamSpec<CsgNodeDraft>> csgBoxTable() {
    static const std::vector<ParamSpec<CsgNodeDraft>> rows = withDefaults(lift(&CsgNodeDraft::node, transformRows<CsgNode>()));
    return rows;
}

std::span<const ParamSpec<CsgNodeDraft>> csgCylinderTable() {
    static const std::vector<ParamSpec<CsgNodeDraft>> rows = withDefaults(
        concat<ParamSpec<CsgNodeDraft>>({lift(&CsgNodeDraft::node, cylinderRows<CsgNode>()), lift(&CsgNodeDraft::node, transformRows<CsgNode>())}));
    return rows;
}

namespace {

// LeftType, LeftIndex, RightType, RightIndex: all required.
std::vector<ParamSpec<CsgNodeDraft>> csgChildRows() {
    auto index = [](std::string_view name, std::string_view doc, int CsgNodeDraft::*member, SourceLocation CsgNodeDraft::*at) {
        return field(name, member, doc, Check::NonNegative, ValueUnit::None, at);
    };
    std::vector<ParamSpec<CsgNodeDraft>> rows = {
        nameRefRow<CsgNodeDraft>({.name = "LeftType", .doc = "Sphere, Box, Cylinder, Operation, Union, Difference or Intersection"},
                      [](auto& n) -> auto& { return n.leftType; }),
        index("LeftIndex", "index among the blocks of LeftType, from 0", &CsgNodeDraft::leftIndex, &CsgNodeDraft::leftIndexAt),
        nameRefRow<CsgNodeDraft>({.name = "RightType", .doc = "as LeftType"}, [](auto& n) -> auto& { return n.rightType; }),
        index("RightIndex", "as LeftIndex", &CsgNodeDraft::rightIndex, &CsgNodeDraft::rightIndexAt),
    };
    for (ParamSpec<CsgNodeDraft>& row : rows) row.info.required = true;
    return rows;
}

}  // namespace

std::span<const ParamSpec<CsgNodeDraft>> csgOperationTable() {
    static const std::vector<ParamSpec<CsgNodeDraft>> rows =
        withDefaults(concat<ParamSpec<CsgNodeDraft>>({csgChildRows(), lift(&CsgNodeDraft::node, transformRows<CsgNode>())}));
    return rows;
}

const std::vector<BlockInfo>& sceneBlocks() {
    static const std::vector<BlockInfo> blocks = {
        infoOf("SceneSettings", sceneSettingsTable()), infoOf("Camera", cameraTable()),
        infoOf("Texture", textureTable()),             infoOf("Material", materialTable()),
#define TRAZO_X(Shape, array, Kind, keyword) infoOf(keyword, objectTable<Kind>()),
        TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
#define TRAZO_X(Data, array, Kind, keyword, ...) infoOf(keyword, lightTable<Kind>()),
        TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    };
    return blocks;
}

const std::vector<BlockInfo>& csgBlocks() {
    static const std::vector<BlockInfo> blocks = {
        infoOf("Sphere", csgSphereTable()),       infoOf("Box", csgBoxTable()),
        infoOf("Cylinder", csgCylinderTable()),   infoOf("Union", csgOperationTable()),
        infoOf("Difference", csgOperationTable()), infoOf("Intersection", csgOperationTable()),
    };
    return blocks;
}

std::vector<std::string_view> blockNames(const std::vector<BlockInfo>& blocks) {
    std::vector<std::string_view> names;
    for (const BlockInfo& b : blocks) names.push_back(b.name);
    return names;
}

}  // namespace trazo
