// Flattening of the host scene into the arrays kernels read, and the scene's feature mask.
#include "flatten/flatten.h"
#include "flatten/environment_tables.h"
#include "flatten/flatten_csg.h"
#include "flatten/flatten_mesh.h"
#include "flatten/mesh_reuse.h"

#include "accel/bvh_build.h"
#include "accel/collapse_bvh.h"
#include "core/srgb.h"
#include "objects/visit_object.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace trazo {

namespace {


MaterialData toMaterialData(const Material& m) {
    MaterialData d{};
#define TRAZO_X(HostType, hostName, fallback, Type, name, toKernel, ...) d.name = toKernel(m.hostName);
#define TRAZO_NO_SLOTS()
    TRAZO_MATERIAL_FIELDS(TRAZO_X, TRAZO_NO_SLOTS)
#undef TRAZO_NO_SLOTS
#undef TRAZO_X
    for (int s = 0; s < kTextureSlotCount; ++s) d.textures[s] = m.textures[size_t(s)];
    return d;
}

// Materials used by objects, with the default material appended when some object omits one.
struct MaterialTable {
    std::vector<MaterialData> data;
    uint32_t defaultIndex = 0;
    bool defaultUsed = false;

    explicit MaterialTable(const Scene& scene) {
        for (const Material& m : scene.materials) data.push_back(toMaterialData(m));
        defaultIndex = (uint32_t)data.size();
        data.push_back(toMaterialData(Material{}));
    }
    uint32_t index(int32_t material) {
        if (material == kDefaultMaterial) {
            defaultUsed = true;
            return defaultIndex;
        }
        return (uint32_t)material;
    }
};

// A warning at the object's block when its material has textures its kind gives no coordinates for.
template <class Host, class Shape>
void warnIfTexturesIgnored(const Scene& scene, const Host& object, const char* keyword, const SceneArrays& out,
                           const Shape& shape, Diagnostics& warnings) {
    if (object.material == kDefaultMaterial || !scene.materials[object.material].usesTextures()) return;
    if (objectHasUvs(hostView(out), shape)) return;
    std::string what = keyword;
    if constexpr (requires { object.source; }) what += " '" + object.source + "'";
    warnings.warning(object.where, what + " has no texture coordinates; the textures of material '" +
                                       scene.materials[object.material].name + "' are ignored for it");
}

// Texels of the textures that materials use, each stored once per decoding, and the materials' indices remapped
// to them. Under `Integrator path` an 8-bit colour texture is decoded from sRGB (SPEC §7 Surfaces); normal maps
// and float images are used as stored, so an 8-bit image that is both a normal map and a colour gets two copies.
void flattenTextures(const Scene& scene, SceneArrays& out) {
    const bool decodeColours = scene.settings.integrator == IntegratorKind::Path;
    std::vector<int32_t> remap(2 * scene.textures.size(), -1);  // [2·index + decoded]
    auto place = [&](int32_t& index, bool colour) {
        if (index < 0) return;
        const TextureImage& image = *scene.textures[index].image;
        const bool decoded = colour && decodeColours && image.eightBit;
        int32_t& placed = remap[2 * size_t(index) + decoded];
        if (placed < 0) {
            placed = (int32_t)out.textures.size();
            out.textures.push_back({(uint32_t)out.texels.size(), (uint32_t)image.width, (uint32_t)image.height});
            out.texels.insert(out.texels.end(), image.texels.begin(), image.texels.end());
            if (decoded)
                for (size_t t = out.texels.size() - image.texels.size(); t < out.texels.size(); ++t)
                    out.texels[t] = linearFromSrgb(out.texels[t]);
        }
        index = placed;
    };
    for (MaterialData& m : out.materials)
        for (int slot = 0; slot < kTextureSlotCount; ++slot) place(m.textures[slot], slot != kNormalTexture);
}

// The object's bounds, padded: the shapes' own tests are exact, the box test must never be the one that misses.
Aabb paddedBounds(const SceneView& view, const ObjectRef& o) {
    const Aabb b = visitObject(view, o, [&](const auto& shape) { return objectBounds(view, shape); });
    if (b.empty()) return Aabb{Vec3(0.0f), Vec3(0.0f)};  // an empty CSG solid: never hit anyway
    return b.padded();
}

// The top-level BVH over every object; objects (and their sources) are reordered into its leaf order.
void buildTopLevel(SceneArrays& out, std::vector<ObjectId>& sources) {
    std::vector<Aabb> bounds;
    const SceneView view = hostView(out);
    for (const ObjectRef& o : out.objects) bounds.push_back(paddedBounds(view, o));
    BvhBuildOptions options;
    options.maxLeafSize = 2;
    Bvh bvh = buildBvh(bounds, options);
    std::vector<ObjectRef> ordered;
    std::vector<ObjectId> orderedSources;
    for (uint32_t old : bvh.primitiveOrder) {
        ordered.push_back(out.objects[old]);
        orderedSources.push_back(sources[old]);
    }
    out.objects = std::move(ordered);
    sources = std::move(orderedSources);
    out.topNodes = collapseBvh(bvh);
}

uint32_t traversalStackNeed(const SceneArrays& a) {
    uint32_t meshNeed = 0;
    for (uint32_t i = 0; i < a.meshes.size(); ++i) {
        const WideBvhNode* nodes = a.meshNodes.data() + a.meshes[i].nodeOffset;
        meshNeed = std::max(meshNeed, wideBvhStackNeed(nodes, meshNodeCount(a, i)));
    }
    return wideBvhStackNeed(a.topNodes.data(), a.topNodes.size()) + meshNeed;
}

}  // namespace

FlattenResult flatten(const Scene& scene, FlattenResult* previous) {
    FlattenResult result;
    SceneArrays& out = result.arrays;
    MaterialTable materials(scene);
    const SceneSettings& s = scene.settings;
    placeMeshes(scene, previous, result);  // meshes first: only they write the mesh arrays

    // Every object of every kind, kind by kind in the order of objects/object_kind_list.h.
    auto add = [&](ObjectKind kind, const char* keyword, uint32_t hostIndex, const auto& object, const auto& shapes) {
        uint32_t index = 0;
        if constexpr (std::is_same_v<std::decay_t<decltype(object)>, Mesh>) {
            if (result.meshes[hostIndex].shape < 0) return;
            index = (uint32_t)result.meshes[hostIndex].shape;
        } else if (!appendObject(object, out, index)) {
            return;
        }
        out.objects.push_back({kind, index, materials.index(object.material)});
        result.sources.push_back(ObjectId::of(kind, hostIndex));
        warnIfTexturesIgnored(scene, object, keyword, out, shapes[index], result.warnings);
    };
#define TRAZO_X(Shape, array, Kind, keyword)                  \
    for (uint32_t i = 0; i < (uint32_t)scene.array.size(); ++i) \
        add(ObjectKind::Kind, keyword, i, scene.array[i], out.array);
    TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
    buildTopLevel(out, result.sources);
    out.traversalStackNeed = traversalStackNeed(out);
    if (!materials.defaultUsed) materials.data.pop_back();
    out.materials = std::move(materials.data);
    flattenTextures(scene, out);
    appendEnvironment(s.backgroundColor, s.environmentRotation, s.environmentImage.get(), out);

#define TRAZO_X(Data, array, Kind, ...) \
    for (const Kind& light : scene.array) appendLight(light, out);
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X

    const Camera& c = scene.camera;
    const float focus = c.focalDistance > 0.0f ? c.focalDistance : length(c.poi - c.pov);  // 0: POI is in focus
    out.settings = RenderSettings{s.backgroundColor, (uint32_t)s.reflectionQuality, (uint32_t)s.reflectionSteps,
                                  (uint32_t)s.indirectQuality, s.colorBleeding, (uint32_t)s.antialiasing,
                                  c.aperture, focus, (uint32_t)std::max(c.lensQuality, 1), s.integrator,
                                  (uint32_t)std::clamp(s.maxBounces, 0, kMaxBounces), s.lightSampling};

    FeatureMask f = 0;
#define TRAZO_X(Data, array, Kind, keyword, label, feature) \
    if (!out.array.empty()) f |= feature;
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    for (const ObjectRef& o : out.objects) f |= materialFeatures(out.materials[o.material], out.settings);
    if (s.indirectQuality >= 1 && s.colorBleeding > 0.0f) f |= kFeatureIndirect;
    if (!scene.meshes.empty()) f |= kFeatureMeshes;
    if (!scene.csgs.empty()) f |= kFeatureCsg;
    if (!out.environment.empty() && out.environment[0].texture >= 0) f |= kFeatureEnvironmentMap;
    out.features = f;

    return result;
}

}  // namespace trazo
