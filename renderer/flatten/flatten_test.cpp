// flatten(): every drawn object maps back to its host object through `sources` after the top-level BVH
// reorders them, and reusing an earlier result's meshes gives the same bytes as flattening from scratch
// (every shipped scene, after edits and after edits undone).
#include "flatten/flatten.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <functional>

#include "fetched_assets.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace trazo {
namespace {

// A unit square in the xy plane as two triangles, no normals or uvs.
std::shared_ptr<const MeshData> squareMesh() {
    auto data = std::make_shared<MeshData>();
    data->positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    data->corners = {{0, -1, -1}, {1, -1, -1}, {2, -1, -1}, {0, -1, -1}, {2, -1, -1}, {3, -1, -1}};
    return data;
}

Mesh meshAt(std::shared_ptr<const MeshData> data, Vec3 offset) {
    Mesh m;
    m.data = std::move(data);
    m.transforms.push_back({TransformStep::Kind::Translation, offset, 0.0f});
    return m;
}

// Objects of every kind spread so the top-level BVH's leaf order is not the kinds' order.
Scene mixedScene() {
    Scene s;
    for (int i = 0; i < 4; ++i) s.spheres.push_back(Sphere{kDefaultMaterial, Vec3(float(7 * i % 5), 0, 0), 0.25f + 0.01f * i, {}});
    Box box;
    box.transforms.push_back({TransformStep::Kind::Translation, Vec3(2.5f, 0, 0), 0.0f});
    s.boxes.push_back(box);
    Cylinder cylinder;
    cylinder.base = Vec3(0.5f, 0, 0);
    s.cylinders.push_back(cylinder);
    auto tree = std::make_shared<CsgTree>();  // a CSG solid of one sphere, at x 1.5
    CsgNode ball;
    ball.center = Vec3(1.5f, 0, 0);
    ball.radius = 0.2f;
    tree->nodes.push_back(ball);
    tree->root = 0;
    Csg csg;
    csg.tree = tree;
    s.csgs.push_back(csg);
    s.meshes.push_back(meshAt(std::make_shared<MeshData>(), Vec3(0)));  // no triangles: draws nothing
    s.meshes.push_back(meshAt(squareMesh(), Vec3(3.5f, 0, 0)));
    s.meshes.push_back(meshAt(squareMesh(), Vec3(-1, 0, 0)));
    return s;
}

TEST(Flatten, SourcesMapEveryObjectBackToItsHostObject) {
    const Scene scene = mixedScene();
    const FlattenResult flat = flatten(scene);
    const SceneArrays& a = flat.arrays;
    ASSERT_EQ(flat.sources.size(), a.objects.size());
    ASSERT_EQ(a.objects.size(), 4u + 1 + 1 + 1 + 2);  // the empty mesh has no entry
    bool reordered = false;
    std::vector<ObjectId> seen;
    for (size_t i = 0; i < a.objects.size(); ++i) {
        const ObjectId id = flat.sources[i];
        const ObjectRef& o = a.objects[i];
        ASSERT_EQ(id.objectKind(), o.kind);
        seen.push_back(id);
        if (i > 0 && uint32_t(flat.sources[i - 1].kind) > uint32_t(id.kind)) reordered = true;
        switch (o.kind) {
        case ObjectKind::Sphere:  // the shape is the host sphere's
            EXPECT_EQ(a.spheres[o.index].center.x, scene.spheres[id.index].center.x);
            EXPECT_EQ(a.spheres[o.index].radius, scene.spheres[id.index].radius);
            break;
        case ObjectKind::Mesh: {  // host mesh 1 sits at x 3.5, mesh 2 at x -1
            ASSERT_TRUE(id.index == 1 || id.index == 2);
            const MeshShape& m = a.meshes[o.index];
            EXPECT_EQ(a.triangles[m.triangleOffset].p0.x >= 3.5f, id.index == 1);
            EXPECT_EQ(flat.meshes[id.index].shape, int32_t(o.index));
            break;
        }
        case ObjectKind::Csg:
            EXPECT_EQ(id.index, 0u);
        {
            const Aabb b = objectBounds(hostView(a), a.csgs[o.index]);
            EXPECT_NEAR(0.5f * (b.min.x + b.max.x), 1.5f, 1e-4f);
        }
            break;
        default:
            EXPECT_EQ(id.index, 0u);  // one box, one cylinder
        }
    }
    EXPECT_TRUE(reordered) << "the test needs the BVH to reorder kinds";
    for (const ObjectId& id : seen) EXPECT_EQ(std::count(seen.begin(), seen.end(), id), 1);
    EXPECT_EQ(flat.meshes[0].shape, -1);
}

// Every array, value and source of two results, byte for byte.
void expectSameBytes(const FlattenResult& x, const FlattenResult& y, const std::string& what) {
    EXPECT_EQ(describeArrays(changedArrays(x.arrays, y.arrays)), "none") << what;
    ASSERT_EQ(x.sources.size(), y.sources.size()) << what;
    for (size_t i = 0; i < x.sources.size(); ++i) EXPECT_EQ(x.sources[i], y.sources[i]) << what;
    EXPECT_EQ(x.warnings.items.size(), y.warnings.items.size()) << what;
}

Scene readShipped(const std::string& name) { return test::readSourceScene("scenes/" + name); }

std::vector<std::string> shippedScenes() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(test::sourcePath("scenes")))
        if (entry.path().extension() == ".scene") names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// The edits a user makes: move the first object of some kind, move a mesh, add a copy of a mesh, delete one.
std::vector<std::pair<std::string, std::function<void(Scene&)>>> edits() {
    return {
        {"move a sphere", [](Scene& s) { if (!s.spheres.empty()) s.spheres[0].center += Vec3(0.25f, 0, 0); }},
        {"move a mesh", [](Scene& s) {
             if (!s.meshes.empty()) s.meshes[0].transforms.push_back({TransformStep::Kind::Translation, Vec3(0, 0.5f, 0), 0.0f});
         }},
        {"duplicate a mesh", [](Scene& s) { if (!s.meshes.empty()) s.meshes.insert(s.meshes.begin(), s.meshes.back()); }},
        {"delete the first mesh", [](Scene& s) { if (!s.meshes.empty()) s.meshes.erase(s.meshes.begin()); }},
        {"recolour a material", [](Scene& s) { if (!s.materials.empty()) s.materials[0].diffuseColor = Vec3(0.1f, 0.2f, 0.3f); }},
        {"add a sphere", [](Scene& s) { s.spheres.push_back(Sphere{kDefaultMaterial, Vec3(0, 1, 0), 0.5f, {}}); }},
    };
}

TEST(Flatten, ReuseGivesTheBytesOfAFreshFlattenOnEveryShippedScene) {
    int scenes = 0;
    for (const std::string& name : shippedScenes()) {
        if (!test::absentFetchedAsset(test::sourcePath("scenes/" + name)).empty()) continue;
        ++scenes;
        const Scene original = readShipped(name);
        const FlattenResult fresh = flatten(original);
        for (const auto& [what, edit] : edits()) {
            const std::string where = name + ", " + what;
            FlattenResult current = fresh;  // a copy: the reusing flatten takes arrays out of it
            Scene edited = original;
            edit(edited);
            FlattenResult afterEdit = flatten(edited, &current);
            expectSameBytes(afterEdit, flatten(edited), where + " (vs a fresh flatten of the edited scene)");
            FlattenResult back = flatten(original, &afterEdit);
            expectSameBytes(back, fresh, where + " and back");
            if (what == "recolour a material" || what == "move a sphere") {  // no mesh changed: none built
                EXPECT_EQ(afterEdit.meshesBuilt, 0u) << where;
            }
        }
        FlattenResult again = fresh;
        const FlattenResult unchanged = flatten(original, &again);
        expectSameBytes(unchanged, fresh, name + ", unedited");
        EXPECT_EQ(unchanged.reused, kMeshArrays) << name;
        EXPECT_EQ(unchanged.meshesBuilt, 0u) << name;
        EXPECT_EQ(unchanged.meshesReused, uint32_t(original.meshes.size())) << name;
    }
    EXPECT_GE(scenes, 10);
}

// A mesh moved among others is rebuilt alone; the others are copied to their new places.
TEST(Flatten, MovingOneMeshRebuildsOnlyIt) {
    Scene scene = mixedScene();
    FlattenResult before = flatten(scene);
    scene.meshes[2].transforms[0].value = Vec3(-2, 0, 0);
    const FlattenResult after = flatten(scene, &before);
    EXPECT_EQ(after.meshesBuilt, 1u);
    EXPECT_EQ(after.meshesReused, 1u);
    EXPECT_EQ(after.reused, kNoArrays);
    expectSameBytes(after, flatten(scene), "one mesh moved");
    // Mesh 1 first, with the mesh arrays' sizes unchanged: the moved mesh's nodes and triangles are all that
    // differ (a translation leaves its corners' normals and uvs as they were).
    EXPECT_EQ(describeArrays(changedArrays(before.arrays, after.arrays) & kMeshArrays), "meshNodes triangles");
}

TEST(ArrayMask, NamesFollowTheArrayList) {
    EXPECT_EQ(describeArrays(kNoArrays), "none");
    EXPECT_EQ(describeArrays(maskOf(SceneArray::spheres) | maskOf(SceneArray::topNodes) | maskOf(SceneArray::values)),
              "spheres topNodes values");
    EXPECT_EQ(describeArrays(kMeshArrays), "meshes meshNodes triangles triangleCorners");
    SceneArrays a, b;
    a.materials.resize(2);
    b.materials.resize(2);
    EXPECT_EQ(changedArrays(a, b), kNoArrays);
    b.materials[1].roughness = 0.5f;
    b.settings.antialiasing = 4;
    EXPECT_EQ(describeArrays(changedArrays(a, b)), "materials values");
    EXPECT_EQ(describeArrays(changedArrays(a, b, maskOf(SceneArray::materials))), "values");
}

}  // namespace
}  // namespace trazo
