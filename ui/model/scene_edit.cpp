// Object and light edits on the host scene: each kind's vector found through one switch over ObjectId::Kind.
#include "model/scene_edit.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "flatten/flatten.h"
#include "io/text_file.h"
#include "scene/csg_reader.h"
#include "scene/obj_reader.h"
#include "scene/transform_checks.h"

namespace trazo {
namespace {

using Step = TransformStep::Kind;

// Calls f with the scene's vector of `kind` (Scene::spheres, ..., Scene::areaLights).
template <class SceneRef, class F>
decltype(auto) visitKind(SceneRef& scene, ObjectId::Kind kind, F&& f) {
    switch (kind) {
#define TRAZO_X(Shape, array, HostKind, keyword) \
    case ObjectId::Kind::HostKind: return f(scene.array);
        TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
#define TRAZO_X(Data, array, HostKind, ...) \
    case ObjectId::Kind::HostKind: return f(scene.array);
        TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    }
    TRAZO_UNREACHABLE();
}

template <class T>
constexpr bool kHasTransforms = requires(T t) { t.transforms; };
template <class T>
constexpr bool kHasMaterial = requires(T t) { t.material; };

// A Mesh's file: shared with another object of the scene that names it, else read. Null after reporting.
std::shared_ptr<const MeshData> loadMeshData(const Scene& scene, const std::string& path, Diagnostics& diags) {
    for (const Mesh& m : scene.meshes)
        if (m.data && m.source == path) return m.data;
    std::shared_ptr<const MeshData> data = readObjFile(path, diags);
    if (!data) return nullptr;
    if (const std::string problem = meshExtentProblem(*data, {}); !problem.empty()) {
        diags.error({path, 0, 0}, "the mesh " + problem);
        return nullptr;
    }
    return data;
}

// A CSG's file, shared or read as a Mesh's.
std::shared_ptr<const CsgTree> loadCsgTree(const Scene& scene, const std::string& path, Diagnostics& diags) {
    for (const Csg& c : scene.csgs)
        if (c.tree && c.source == path) return c.tree;
    return readCsgFile(path, diags);
}

// Reads `written` (relative to the scene's folder) into a Mesh's or CSG's source and data; false after
// reporting, with `object` unchanged.
template <class T>
bool loadInto(const Scene& scene, T& object, const std::string& written, Diagnostics& diags) {
    const std::string path = resolveRelativePath(scene.path, written);
    const size_t before = diags.items.size();
    auto loaded = [&] {  // read, and nothing reported as an error on the way (a CSG's warnings may come)
        for (size_t i = before; i < diags.items.size(); ++i)
            if (diags.items[i].severity == Severity::Error) return false;
        return true;
    };
    if constexpr (std::is_same_v<T, Mesh>) {
        auto data = loadMeshData(scene, path, diags);
        if (!data || !loaded()) return false;
        object.data = std::move(data);
    } else {
        auto tree = loadCsgTree(scene, path, diags);
        if (!tree || !loaded()) return false;
        object.tree = std::move(tree);
    }
    object.source = path;
    return true;
}

template <class T>
void clearWhere(T& object) {
    object.where = {};
    if constexpr (std::is_same_v<T, AreaLight>) object.subdivisionAt = {};
}

bool validSize(float size) { return std::isfinite(size) && size > 0.0f && size <= 1e18f; }

}  // namespace

const char* kindKeyword(ObjectId::Kind kind) {
    switch (kind) {
#define TRAZO_X(Shape, array, HostKind, keyword) \
    case ObjectId::Kind::HostKind: return keyword;
        TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
#define TRAZO_X(Data, array, HostKind, keyword, ...) \
    case ObjectId::Kind::HostKind: return keyword;
        TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    }
    TRAZO_UNREACHABLE();
}

size_t objectCount(const Scene& scene, ObjectId::Kind kind) {
    return visitKind(scene, kind, [](const auto& objects) { return objects.size(); });
}

bool isValidObject(const Scene& scene, ObjectId id) {
    return uint32_t(id.kind) < uint32_t(kObjectIdKindCount) && id.index < objectCount(scene, id.kind);
}

std::vector<ObjectId> listObjects(const Scene& scene) {
    std::vector<ObjectId> ids;
    for (int k = 0; k < kObjectIdKindCount; ++k) {
        const auto kind = ObjectId::Kind(k);
        for (size_t i = 0; i < objectCount(scene, kind); ++i) ids.push_back({kind, uint32_t(i)});
    }
    return ids;
}

std::string describeObject(const Scene& scene, ObjectId id) {
    if (!isValidObject(scene, id)) return "(none)";
    const std::string index = std::to_string(id.index);
#define TRAZO_X(Data, array, HostKind, keyword, label, ...) \
    if (id.kind == ObjectId::Kind::HostKind) return label + (" " + index);
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    const int32_t m = objectMaterial(scene, id);
    std::string what = m >= 0 && size_t(m) < scene.materials.size() ? scene.materials[size_t(m)].name : "default";
    std::string file;
    if (id.kind == ObjectId::Kind::Mesh) file = scene.meshes[id.index].source;
    if (id.kind == ObjectId::Kind::Csg) file = scene.csgs[id.index].source;
    if (!file.empty()) what = std::filesystem::path(file).filename().string() + ", " + what;
    return std::string(kindKeyword(id.kind)) + " " + index + " (" + what + ")";
}

const SourceLocation& objectWhere(const Scene& scene, ObjectId id) {
    return visitKind(scene, id.kind, [&](const auto& objects) -> const SourceLocation& { return objects.at(id.index).where; });
}

int32_t objectMaterial(const Scene& scene, ObjectId id) {
    return visitKind(scene, id.kind, [&](const auto& objects) -> int32_t {
        if constexpr (kHasMaterial<typename std::decay_t<decltype(objects)>::value_type>)
            return objects.at(id.index).material;
        return kDefaultMaterial;
    });
}

void setObjectMaterial(Scene& scene, ObjectId id, int32_t material) {
    visitKind(scene, id.kind, [&](auto& objects) {
        if constexpr (kHasMaterial<typename std::decay_t<decltype(objects)>::value_type>)
            objects.at(id.index).material = material;
    });
}

std::vector<TransformStep>* objectTransforms(Scene& scene, ObjectId id) {
    return visitKind(scene, id.kind, [&](auto& objects) -> std::vector<TransformStep>* {
        if constexpr (kHasTransforms<typename std::decay_t<decltype(objects)>::value_type>)
            return &objects.at(id.index).transforms;
        return nullptr;
    });
}

Aabb objectWorldBounds(const Scene& scene, ObjectId id) {
    return visitKind(scene, id.kind, [&](const auto& objects) { return hostBounds(objects.at(id.index)); });
}

Vec3 objectAnchor(const Scene& scene, ObjectId id) {
#define TRAZO_X(Data, array, HostKind, ...) \
    if (id.kind == ObjectId::Kind::HostKind) return scene.array.at(id.index).position;
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    const Aabb b = objectWorldBounds(scene, id);
    return b.empty() ? Vec3(0, 0, 0) : b.centroid();
}

float newObjectSize(const Camera& camera) {
    const float distance = length(camera.poi - camera.pov);
    const float size = 0.4f * distance * std::tan(0.5f * camera.fovDegrees * float(3.14159265358979323846 / 180.0));
    return validSize(size) ? size : 1.0f;
}

ObjectId addObject(Scene& scene, ObjectId::Kind kind, Vec3 at, float size) {
    if (!validSize(size)) size = 1.0f;
    return visitKind(scene, kind, [&](auto& objects) {
        using T = typename std::decay_t<decltype(objects)>::value_type;
        std::optional<T> added = newObject(KindTag<T>{}, at, size);
        if (!added) return ObjectId{kind, uint32_t(objects.size())};  // read from a file: addObjectFromFile
        objects.push_back(std::move(*added));
        return ObjectId{kind, uint32_t(objects.size() - 1)};
    });
}

std::optional<ObjectId> addObjectFromFile(Scene& scene, ObjectId::Kind kind, const std::string& path, Vec3 at,
                                          Diagnostics& diags) {
    if (path.empty()) {
        diags.error({}, std::string("no file given for the new ") + kindKeyword(kind));
        return std::nullopt;
    }
    auto place = [&](auto& objects) -> std::optional<ObjectId> {
        using T = typename std::decay_t<decltype(objects)>::value_type;
        if constexpr (std::is_same_v<T, Mesh> || std::is_same_v<T, Csg>) {  // loadInto reads their files
            T object;
            if (!loadInto(scene, object, path, diags)) return std::nullopt;
            const Aabb b = hostBounds(object);
            translateSteps(object.transforms, b.empty() ? at : at - b.centroid());
            objects.push_back(std::move(object));
            return ObjectId{kind, uint32_t(objects.size() - 1)};
        }
        diags.error({}, std::string("a ") + kindKeyword(kind) + " is not read from a file");
        return std::nullopt;
    };
    return visitKind(scene, kind, place);
}

bool replaceObjectSource(Scene& scene, ObjectId id, const std::string& path, Diagnostics& diags) {
    if (!isValidObject(scene, id)) return false;
    return visitKind(scene, id.kind, [&](auto& objects) {
        using T = typename std::decay_t<decltype(objects)>::value_type;
        if constexpr (std::is_same_v<T, Mesh> || std::is_same_v<T, Csg>) {
            T object = objects[id.index];
            if (!loadInto(scene, object, path, diags)) return false;
            objects[id.index] = std::move(object);
            return true;
        }
        return false;
    });
}

ObjectId duplicateObject(Scene& scene, ObjectId id, Vec3 offset) {
    const ObjectId copy = visitKind(scene, id.kind, [&](auto& objects) {
        auto object = objects.at(id.index);
        clearWhere(object);
        objects.push_back(std::move(object));
        return ObjectId{id.kind, uint32_t(objects.size() - 1)};
    });
    translateObject(scene, copy, offset);
    return copy;
}

std::optional<ObjectId> deleteObject(Scene& scene, ObjectId id) {
    const size_t left = visitKind(scene, id.kind, [&](auto& objects) {
        objects.erase(objects.begin() + std::ptrdiff_t(id.index));
        return objects.size();
    });
    if (id.index < left) return id;
    if (left > 0) return ObjectId{id.kind, uint32_t(left - 1)};
    return std::nullopt;
}

std::optional<ObjectId> idAfterDelete(ObjectId deleted, ObjectId id) {
    if (id == deleted) return std::nullopt;
    if (id.kind == deleted.kind && id.index > deleted.index) return ObjectId{id.kind, id.index - 1};
    return id;
}

void translateObject(Scene& scene, ObjectId id, Vec3 delta) {
    visitKind(scene, id.kind, [&](auto& objects) { translate(objects.at(id.index), delta); });
}

void insertTransformStep(std::vector<TransformStep>& steps, size_t at, TransformStep::Kind kind) {
    TransformStep step{kind, Vec3(0, 0, 0), 0.0f};
    if (kind == Step::Rotation) step.value = Vec3(0, 1, 0);
    if (kind == Step::Scale) step.value = Vec3(1, 1, 1);
    steps.insert(steps.begin() + std::ptrdiff_t(std::min(at, steps.size())), step);
}

bool moveTransformStep(std::vector<TransformStep>& steps, size_t i, int direction) {
    const size_t j = direction < 0 ? i - 1 : i + 1;  // i − 1 wraps past any size when i is 0
    if (i >= steps.size() || j >= steps.size()) return false;
    std::swap(steps[i], steps[j]);
    return true;
}

std::string transformProblem(const std::vector<TransformStep>& steps, ObjectId::Kind kind, const MeshData* mesh) {
    // The reader's checks, in its order (scene/transform_checks.h).
    if (std::string problem = invertibleProblem(steps); !problem.empty()) return problem;
    if (kind == ObjectId::Kind::Box) return boxNormalsProblem(steps);
    if (kind == ObjectId::Kind::Mesh && mesh) {
        if (std::string problem = meshExtentProblem(*mesh, steps); !problem.empty()) return "the mesh " + problem;
    }
    return {};
}

}  // namespace trazo
