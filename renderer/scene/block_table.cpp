// Block tables (host): the parameters of every block as SPEC.md §3–§4 lists them, and the checks on values.
#include "scene/block_table.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>

namespace trazo {
namespace {

using K = ValueKind;
using C = ValueCheck;
using Step = TransformStep::Kind;

template <class D>
std::vector<TransformStep>& transformsOf(D& d) {
    if constexpr (requires { d.node; }) {
        return d.node.transforms;
    } else {
        return d.object.transforms;
    }
}

template <class D>
void addTranslation(D& d, const ParamValue& v) { transformsOf(d).push_back({Step::Translation, v.vec3(), 0}); }
template <class D>
void addRotation(D& d, const ParamValue& v) { transformsOf(d).push_back({Step::Rotation, v.vec3(), float(v.numbers[3])}); }
template <class D>
void addScale(D& d, const ParamValue& v) { transformsOf(d).push_back({Step::Scale, v.vec3(), 0}); }
template <class D>
void setMaterial(D& d, const ParamValue& v) { d.material = {v.text, v.at}; }
template <class D>
void setSource(D& d, const ParamValue& v) {
    d.object.source = v.text;
    d.sourceAt = v.at;
}

constexpr ParamInfo kTranslation{"Translation", K::Real, 3, "", "translate by x y z (in written order)", C::None, true};
constexpr ParamInfo kRotation{"Rotation", K::Real, 4, "", "rotate about axis x y z by an angle in radians",
                              C::RotationAxis, true};
constexpr ParamInfo kScale{"Scale", K::Real, 3, "", "scale by sx sy sz about the origin", C::NonZeroComponents, true};
constexpr ParamInfo kMaterial{"Material", K::Name, 1, "", "material name (the Material defaults, with a warning)"};

std::string lower(std::string_view s) {
    std::string r(s);
    for (char& c : r) c = char(std::tolower(static_cast<unsigned char>(c)));
    return r;
}

size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

std::string kindWord(ValueKind kind, int count) {
    const bool plural = count != 1;
    switch (kind) {
        case K::Real: return plural ? "numbers" : "number";
        case K::Int: return plural ? "integers" : "integer";
        case K::Name: return plural ? "names" : "name";
        case K::Path: return plural ? "paths in double quotes" : "path in double quotes";
    }
    return "values";
}

bool isInteger(const std::string& text, double& out) {
    const char* first = text.data();
    const char* last = first + text.size();
    if (first != last && *first == '+') ++first;
    long long v = 0;
    auto [ptr, ec] = std::from_chars(first, last, v);
    if (ec != std::errc() || ptr != last || v < INT_MIN || v > INT_MAX) return false;
    out = double(v);
    return true;
}

// The range check of `info` on checked values; reports and returns false when it fails (warnings pass).
bool checkRange(const ParamInfo& info, const ParameterLine& line, size_t offset, ParamValue& v,
                Diagnostics& diags) {
    const std::string name(info.name);
    auto at = [&](int i) { return SourceLocation{v.at.file, line.line, line.values[offset + size_t(i)].column}; };
    auto text = [&](int i) { return line.values[offset + size_t(i)].text; };
    for (int i = 0; i < info.count; ++i) {
        const double x = v.numbers[size_t(i)];
        switch (info.check) {
            case C::Positive:
                if (!(x > 0)) return diags.error(at(i), name + " must be positive, got " + text(i)), false;
                break;
            case C::NonNegative:
                if (x < 0) return diags.error(at(i), name + " must not be negative, got " + text(i)), false;
                break;
            case C::RenderSize:
                if (x < 1 || x > kMaxRenderSize) {
                    return diags.error(at(i), name + " must be between 1 and " + std::to_string(kMaxRenderSize) +
                                                  ", got " + text(i)),
                           false;
                }
                break;
            case C::Antialiasing:
                if (x != 1 && x != 4 && x != 16) {
                    diags.warning(at(i), name + " must be 1, 4 or 16, got " + text(i) + "; using 1");
                    v.numbers[size_t(i)] = 1;
                }
                break;
            case C::NonZeroComponents:
                if (x == 0) {
                    return diags.error(at(i), name + " component must not be zero (a singular transform)"), false;
                }
                break;
            case C::UnitInterval:
                if (x < 0 || x > 1) return diags.error(at(i), name + " must be between 0 and 1, got " + text(i)), false;
                break;
            case C::FieldOfView:
                if (!(x > 0 && x < 180)) {
                    return diags.error(at(i), name + " must be between 0 and 180 degrees (exclusive), got " + text(i)),
                           false;
                }
                break;
            case C::ConeAngle:
                if (x < 0 || x > 180) {
                    return diags.error(at(i), name + " must be between 0 and 180 degrees, got " + text(i)), false;
                }
                break;
            case C::None:
            case C::NonZeroVector:
            case C::RotationAxis: break;
        }
    }
    if (info.check == C::NonZeroVector || info.check == C::RotationAxis) {
        if (v.numbers[0] == 0 && v.numbers[1] == 0 && v.numbers[2] == 0) {
            const std::string what = info.check == C::RotationAxis ? "Rotation axis" : name;
            return diags.error(at(0), what + " must not be a zero-length vector"), false;
        }
    }
    return true;
}

template <class T>
BlockInfo infoOf(std::string_view name, std::span<const ParamSpec<T>> table) {
    BlockInfo b{name, {}};
    for (const ParamSpec<T>& spec : table) b.params.push_back(spec.info);
    return b;
}

}  // namespace

std::span<const ParamSpec<SceneSettings>> sceneSettingsTable() {
    using T = SceneSettings;
    static const ParamSpec<T> table[] = {
        {{"BackgroundColor", K::Real, 3, "0 0 0", "colour of rays that hit nothing"},
         [](T& s, const ParamValue& v) { s.backgroundColor = v.vec3(); }},
        {{"RenderWidth", K::Int, 1, "512", "image width in pixels", C::RenderSize},
         [](T& s, const ParamValue& v) { s.renderWidth = v.integer(); }},
        {{"RenderHeight", K::Int, 1, "512", "image height in pixels", C::RenderSize},
         [](T& s, const ParamValue& v) { s.renderHeight = v.integer(); }},
        {{"ReflectionQuality", K::Int, 1, "3", "q: 2·q² glossy reflection rays", C::NonNegative},
         [](T& s, const ParamValue& v) {
             s.reflectionQuality = v.integer();
             s.reflectionQualityAt = v.at;
         }},
        {{"ReflectionSteps", K::Int, 1, "1", "maximum reflection depth", C::NonNegative},
         [](T& s, const ParamValue& v) {
             s.reflectionSteps = v.integer();
             s.reflectionStepsAt = v.at;
         }},
        {{"IndirectQuality", K::Int, 1, "3", "q: 2·q² hemisphere rays for indirect light", C::NonNegative},
         [](T& s, const ParamValue& v) {
             s.indirectQuality = v.integer();
             s.indirectQualityAt = v.at;
         }},
        {{"ColorBleeding", K::Real, 1, "1.0", "factor on the indirect light"},
         [](T& s, const ParamValue& v) { s.colorBleeding = v.real(); }},
        {{"Antialiasing", K::Int, 1, "1", "samples per pixel: 1, 4 or 16", C::Antialiasing},
         [](T& s, const ParamValue& v) { s.antialiasing = v.integer(); }},
    };
    return table;
}

std::span<const ParamSpec<Camera>> cameraTable() {
    using T = Camera;
    static const ParamSpec<T> table[] = {
        {{"POV", K::Real, 3, "0 0 10", "camera position"}, [](T& c, const ParamValue& v) { c.pov = v.vec3(); }},
        {{"POI", K::Real, 3, "0 0 0", "point looked at"}, [](T& c, const ParamValue& v) { c.poi = v.vec3(); }},
        {{"FOV", K::Real, 1, "45", "vertical field of view in degrees", C::FieldOfView},
         [](T& c, const ParamValue& v) { c.fovDegrees = v.real(); }},
    };
    return table;
}

std::span<const ParamSpec<TextureDraft>> textureTable() {
    using T = TextureDraft;
    static const ParamSpec<T> table[] = {
        {{"Name", K::Name, 1, "—", "name materials use to refer to it"},
         [](T& t, const ParamValue& v) { t.texture.name = v.text; t.nameAt = v.at; }},
        {{"Source", K::Path, 1, "—", "image file, any format FreeImage reads"},
         [](T& t, const ParamValue& v) { t.texture.source = v.text; t.sourceAt = v.at; }},
    };
    return table;
}

std::span<const ParamSpec<MaterialDraft>> materialTable() {
    using T = MaterialDraft;
    static const ParamSpec<T> table[] = {
        {{"Name", K::Name, 1, "—", "name objects use to refer to it"},
         [](T& m, const ParamValue& v) { m.material.name = v.text; m.nameAt = v.at; }},
        {{"DiffuseColor", K::Real, 3, "0.9 0.9 0.9", "diffuse colour (Oren–Nayar)"},
         [](T& m, const ParamValue& v) { m.material.diffuseColor = v.vec3(); }},
        {{"SpecularColor", K::Real, 3, "0.8 0.8 0.8", "specular colour (Cook–Torrance); also tints reflections"},
         [](T& m, const ParamValue& v) { m.material.specularColor = v.vec3(); }},
        {{"EmissiveColor", K::Real, 3, "0 0 0", "colour emitted without lighting"},
         [](T& m, const ParamValue& v) { m.material.emissiveColor = v.vec3(); }},
        {{"DiffuseTexture", K::Name, 1, "", "texture multiplying DiffuseColor"},
         [](T& m, const ParamValue& v) { m.textures[kDiffuseSlot] = {v.text, v.at}; }},
        {{"SpecularTexture", K::Name, 1, "", "texture multiplying SpecularColor"},
         [](T& m, const ParamValue& v) { m.textures[kSpecularSlot] = {v.text, v.at}; }},
        {{"EmissiveTexture", K::Name, 1, "", "texture multiplying EmissiveColor"},
         [](T& m, const ParamValue& v) { m.textures[kEmissiveSlot] = {v.text, v.at}; }},
        {{"NormalTexture", K::Name, 1, "", "tangent-space normal map (meshes only)"},
         [](T& m, const ParamValue& v) { m.textures[kNormalSlot] = {v.text, v.at}; }},
        {{"Roughness", K::Real, 1, "0.5", "0 polished … 1 rough", C::NonNegative},
         [](T& m, const ParamValue& v) { m.material.roughness = v.real(); }},
        {{"Opacity", K::Real, 1, "1", "1 opaque … 0 fully transparent", C::UnitInterval},
         [](T& m, const ParamValue& v) { m.material.opacity = v.real(); }},
        {{"RefractionIndex", K::Real, 1, "1", "index of refraction", C::Positive},
         [](T& m, const ParamValue& v) { m.material.refractionIndex = v.real(); }},
        {{"ReflectionAngle", K::Real, 1, "0", "full cone angle of glossy reflections in degrees; 0 = mirror",
          C::ConeAngle},
         [](T& m, const ParamValue& v) { m.material.reflectionAngleDegrees = v.real(); }},
        {{"ReflectionAmount", K::Real, 1, "0", "blend between lit colour (0) and reflection (1)", C::UnitInterval},
         [](T& m, const ParamValue& v) { m.material.reflectionAmount = v.real(); }},
    };
    return table;
}

std::span<const ParamSpec<ObjectDraft<Sphere>>> sphereTable() {
    using T = ObjectDraft<Sphere>;
    static const ParamSpec<T> table[] = {
        {kMaterial, setMaterial<T>},
        {{"Center", K::Real, 3, "0 0 0", "centre"}, [](T& s, const ParamValue& v) { s.object.center = v.vec3(); }},
        {{"Radius", K::Real, 1, "1", "radius", C::Positive},
         [](T& s, const ParamValue& v) { s.object.radius = v.real(); }},
    };
    return table;
}

std::span<const ParamSpec<ObjectDraft<Box>>> boxTable() {
    using T = ObjectDraft<Box>;
    static const ParamSpec<T> table[] = {
        {kMaterial, setMaterial<T>},
        {kTranslation, addTranslation<T>},
        {kRotation, addRotation<T>},
        {kScale, addScale<T>},
    };
    return table;
}

std::span<const ParamSpec<ObjectDraft<Cylinder>>> cylinderTable() {
    using T = ObjectDraft<Cylinder>;
    static const ParamSpec<T> table[] = {
        {kMaterial, setMaterial<T>},
        {{"Base", K::Real, 3, "0 0 0", "centre of the bottom cap"},
         [](T& c, const ParamValue& v) { c.object.base = v.vec3(); }},
        {{"Axis", K::Real, 3, "0 1 0", "direction from the bottom cap to the top", C::NonZeroVector},
         [](T& c, const ParamValue& v) { c.object.axis = v.vec3(); }},
        {{"Height", K::Real, 1, "1", "length along the axis", C::Positive},
         [](T& c, const ParamValue& v) { c.object.height = v.real(); }},
        {{"Radius", K::Real, 1, "1", "radius", C::Positive},
         [](T& c, const ParamValue& v) { c.object.radius = v.real(); }},
    };
    return table;
}

std::span<const ParamSpec<ObjectDraft<Csg>>> csgTable() {
    using T = ObjectDraft<Csg>;
    static const ParamSpec<T> table[] = {
        {kMaterial, setMaterial<T>},
        {{"Source", K::Path, 1, "—", ".csg file with the tree"}, setSource<T>},
        {kTranslation, addTranslation<T>},
        {kRotation, addRotation<T>},
        {kScale, addScale<T>},
    };
    return table;
}

std::span<const ParamSpec<ObjectDraft<Mesh>>> meshTable() {
    using T = ObjectDraft<Mesh>;
    static const ParamSpec<T> table[] = {
        {kMaterial, setMaterial<T>},
        {{"Source", K::Path, 1, "—", ".obj file"}, setSource<T>},
        {kTranslation, addTranslation<T>},
        {kRotation, addRotation<T>},
        {kScale, addScale<T>},
    };
    return table;
}

std::span<const ParamSpec<PointLight>> pointLightTable() {
    using T = PointLight;
    static const ParamSpec<T> table[] = {
        {{"Position", K::Real, 3, "0 0 0", "position"}, [](T& l, const ParamValue& v) { l.position = v.vec3(); }},
        {{"Color", K::Real, 3, "1 1 1", "colour and intensity (no falloff)"},
         [](T& l, const ParamValue& v) { l.color = v.vec3(); }},
    };
    return table;
}

std::span<const ParamSpec<AreaLight>> areaLightTable() {
    using T = AreaLight;
    static const ParamSpec<T> table[] = {
        {{"Color", K::Real, 3, "1 1 1", "colour and intensity (no falloff)"},
         [](T& l, const ParamValue& v) { l.color = v.vec3(); }},
        {{"Position", K::Real, 3, "0 0 0", "centre of the rectangle"},
         [](T& l, const ParamValue& v) { l.position = v.vec3(); }},
        {{"Direction", K::Real, 3, "0 -1 0", "normal of the rectangle", C::NonZeroVector},
         [](T& l, const ParamValue& v) { l.direction = v.vec3(); }},
        {{"RollAngle", K::Real, 1, "0", "turn of the rectangle about its normal, radians"},
         [](T& l, const ParamValue& v) { l.rollAngle = v.real(); }},
        {{"Width", K::Real, 1, "1", "size along u", C::Positive}, [](T& l, const ParamValue& v) { l.width = v.real(); }},
        {{"Height", K::Real, 1, "1", "size along v", C::Positive},
         [](T& l, const ParamValue& v) { l.height = v.real(); }},
        {{"Subdivision", K::Int, 2, "5 5", "strata across the width and the height", C::Positive},
         [](T& l, const ParamValue& v) {
             l.subdivisionX = v.integer(0);
             l.subdivisionY = v.integer(1);
             l.subdivisionAt = v.at;
         }},
    };
    return table;
}

std::span<const ParamSpec<CsgNodeDraft>> csgSphereTable() {
    using T = CsgNodeDraft;
    static const ParamSpec<T> table[] = {
        {{"Center", K::Real, 3, "0 0 0", "centre"}, [](T& n, const ParamValue& v) { n.node.center = v.vec3(); }},
        {{"Radius", K::Real, 1, "1", "radius", C::Positive}, [](T& n, const ParamValue& v) { n.node.radius = v.real(); }},
        {kTranslation, addTranslation<T>},
        {kRotation, addRotation<T>},
        {kScale, addScale<T>},
    };
    return table;
}

std::span<const ParamSpec<CsgNodeDraft>> csgBoxTable() {
    using T = CsgNodeDraft;
    static const ParamSpec<T> table[] = {
        {kTranslation, addTranslation<T>},
        {kRotation, addRotation<T>},
        {kScale, addScale<T>},
    };
    return table;
}

std::span<const ParamSpec<CsgNodeDraft>> csgCylinderTable() {
    using T = CsgNodeDraft;
    static const ParamSpec<T> table[] = {
        {{"Base", K::Real, 3, "0 0 0", "centre of the bottom cap"},
         [](T& n, const ParamValue& v) { n.node.base = v.vec3(); }},
        {{"Axis", K::Real, 3, "0 1 0", "direction from the bottom cap to the top", C::NonZeroVector},
         [](T& n, const ParamValue& v) { n.node.axis = v.vec3(); }},
        {{"Height", K::Real, 1, "1", "length along the axis", C::Positive},
         [](T& n, const ParamValue& v) { n.node.height = v.real(); }},
        {{"Radius", K::Real, 1, "1", "radius", C::Positive}, [](T& n, const ParamValue& v) { n.node.radius = v.real(); }},
        {kTranslation, addTranslation<T>},
        {kRotation, addRotation<T>},
        {kScale, addScale<T>},
    };
    return table;
}

std::span<const ParamSpec<CsgNodeDraft>> csgOperationTable() {
    using T = CsgNodeDraft;
    static const ParamSpec<T> table[] = {
        {{"LeftType", K::Name, 1, "—", "Sphere, Box, Cylinder, Operation, Union, Difference or Intersection"},
         [](T& n, const ParamValue& v) { n.leftType = {v.text, v.at}; }},
        {{"LeftIndex", K::Int, 1, "—", "index among the blocks of LeftType, from 0", C::NonNegative},
         [](T& n, const ParamValue& v) { n.leftIndex = v.integer(); n.leftIndexAt = v.at; }},
        {{"RightType", K::Name, 1, "—", "as LeftType"}, [](T& n, const ParamValue& v) { n.rightType = {v.text, v.at}; }},
        {{"RightIndex", K::Int, 1, "—", "as LeftIndex", C::NonNegative},
         [](T& n, const ParamValue& v) { n.rightIndex = v.integer(); n.rightIndexAt = v.at; }},
        {kTranslation, addTranslation<T>},
        {kRotation, addRotation<T>},
        {kScale, addScale<T>},
    };
    return table;
}

const std::vector<BlockInfo>& sceneBlocks() {
    static const std::vector<BlockInfo> blocks = {
        infoOf("SceneSettings", sceneSettingsTable()), infoOf("Camera", cameraTable()),
        infoOf("Texture", textureTable()),             infoOf("Material", materialTable()),
        infoOf("Sphere", sphereTable()),               infoOf("Box", boxTable()),
        infoOf("Cylinder", cylinderTable()),           infoOf("CSG", csgTable()),
        infoOf("Mesh", meshTable()),                   infoOf("PointLight", pointLightTable()),
        infoOf("AreaLight", areaLightTable()),
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

std::string didYouMean(std::string_view wrong, const std::vector<std::string_view>& candidates) {
    // Case-insensitive distance, so that "radius" finds "Radius"; only close names are worth a hint.
    const std::string w = lower(wrong);
    std::string_view best;
    size_t bestDistance = SIZE_MAX;
    for (std::string_view c : candidates) {
        const size_t d = editDistance(w, lower(c));
        if (d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    const size_t limit = std::max<size_t>(2, w.size() / 3);
    if (best.empty() || bestDistance > limit) return {};
    return "did you mean '" + std::string(best) + "'?";
}

std::string_view twoWordSynonym(std::string_view first, std::string_view second) {
    if (first == "Roll" && second == "Angle") return "RollAngle";
    if (first == "Reflection" && second == "Angle") return "ReflectionAngle";
    if (first == "Reflection" && second == "Amount") return "ReflectionAmount";
    return {};
}

int checkParameter(const Block& block, const std::vector<ParamInfo>& params, const ParameterLine& line,
                   ParamValue& value, bool& valid, Diagnostics& diags) {
    valid = false;
    const std::string& file = block.where.file;
    value.at = {file, line.line, 0};
    auto find = [&](std::string_view name) {
        for (size_t k = 0; k < params.size(); ++k)
            if (params[k].name == name) return int(k);
        return -1;
    };
    int k = find(line.name);
    size_t offset = 0;  // values consumed by a two-word name
    if (k < 0 && !line.values.empty() && line.values[0].kind == BlockValue::Kind::Name) {
        const std::string_view synonym = twoWordSynonym(line.name, line.values[0].text);
        if (!synonym.empty() && (k = find(synonym)) >= 0) offset = 1;
    }
    if (k < 0) {
        std::vector<std::string_view> names;
        for (const ParamInfo& p : params) names.push_back(p.name);
        diags.error(value.at, "unknown parameter '" + line.name + "' in " + block.identifier,
                    didYouMean(line.name, names));
        return -1;
    }
    const ParamInfo& info = params[size_t(k)];
    const std::string name(info.name);
    const size_t given = line.values.size() - offset;
    if (given != size_t(info.count)) {
        diags.error(value.at, name + " takes " + std::to_string(info.count) + " " + kindWord(info.kind, info.count) +
                                  ", got " + std::to_string(given));
        return k;
    }
    for (size_t i = 0; i < given; ++i) {
        const BlockValue& bv = line.values[offset + i];
        const SourceLocation at{file, line.line, bv.column};
        switch (info.kind) {
            case K::Real:
            case K::Int:
                if (bv.kind != BlockValue::Kind::Number) {
                    diags.error(at, name + ": expected " + (info.kind == K::Int ? "an integer" : "a number") +
                                        ", got '" + bv.text + "'");
                    return k;
                }
                if (!std::isfinite(bv.number) || !std::isfinite(float(bv.number))) {
                    diags.error(at, name + ": '" + bv.text + "' is not a finite number");
                    return k;
                }
                if (info.kind == K::Int && !isInteger(bv.text, value.numbers[i])) {
                    diags.error(at, name + ": expected an integer, got '" + bv.text + "'");
                    return k;
                }
                if (info.kind == K::Real) value.numbers[i] = bv.number;
                break;
            case K::Name:
                if (bv.kind == BlockValue::Kind::Path) {
                    diags.error(at, name + ": expected a name, got a quoted path");
                    return k;
                }
                value.text = bv.text;
                break;
            case K::Path:
                if (bv.kind != BlockValue::Kind::Path) {
                    diags.error(at, name + ": expected a path in double quotes, got '" + bv.text + "'",
                                "write \"" + bv.text + "\"");
                    return k;
                }
                if (bv.text.empty()) {  // it would name the scene's own folder, or nothing
                    diags.error(at, name + ": empty path");
                    return k;
                }
                if (bv.text.find('\0') != std::string::npos) {  // the lexer refuses a NUL; this guards other Blocks
                    diags.error(at, name + ": the path contains a NUL byte");
                    return k;
                }
                value.text = bv.text;
                break;
        }
    }
    valid = checkRange(info, line, offset, value, diags);
    return k;
}

void reportMissingRequired(const Block& block, const std::vector<ParamInfo>& params, const std::vector<bool>& seen,
                           Diagnostics& diags) {
    if (!block.complete) return;  // a refused line may have held it: that line's error says enough
    for (size_t k = 0; k < params.size(); ++k) {
        if (params[k].required() && !seen[k]) {
            diags.error(block.where,
                        "missing required parameter '" + std::string(params[k].name) + "' in " + block.identifier);
        }
    }
}

}  // namespace trazo
