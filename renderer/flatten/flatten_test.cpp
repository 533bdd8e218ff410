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

// SPEC §7 Surfaces: under `Integrator path` 8-bit colour textures are decoded from sRGB; normal maps and float
// images are used as stored, and the thesis's model takes every texture as stored.
struct TexturedScene {
    Scene scene;
    static constexpr float kEncoded = 188.0f / 255.0f;
    // ((188/255 + 0.055) / 1.055)^2.4, worked by hand: the 8-bit texel that stores about 0.5 in sRGB.
    static constexpr float kDecoded = 0.502886f;

    explicit TexturedScene(IntegratorKind integrator) {
        scene.settings.integrator = integrator;
        auto eightBit = std::make_shared<TextureImage>();
        eightBit->width = 2;
        eightBit->height = 1;
        eightBit->texels = {Vec3(kEncoded), Vec3(0.0f, 0.5f, 1.0f)};
        eightBit->eightBit = true;
        auto floats = std::make_shared<TextureImage>(*eightBit);
        floats->eightBit = false;  // an EXR or PFM: radiance-like values, never decoded
        scene.textures = {Texture{"bytes", "bytes.png", eightBit, {}}, Texture{"floats", "floats.exr", floats, {}}};
        Material both;  // the 8-bit image as a colour and as a normal map
        both.name = "both";
        both.textures[kDiffuseTexture] = 0;
        both.textures[kNormalTexture] = 0;
        Material others;  // the same image in the other colour slots, the float image as a colour
        others.name = "others";
        others.textures[kSpecularTexture] = 0;
        others.textures[kEmissiveTexture] = 0;
        others.textures[kDiffuseTexture] = 1;
        scene.materials = {both, others};
        scene.spheres.push_back(Sphere{0, Vec3(0), 1.0f, {}});
        scene.spheres.push_back(Sphere{1, Vec3(3, 0, 0), 1.0f, {}});
    }
};

// The first texel of the texture in `slot` of material `m`.
Vec3 firstTexel(const SceneArrays& a, uint32_t m, int slot) {
    const int32_t t = a.materials[m].textures[slot];
    EXPECT_GE(t, 0);
    return t < 0 ? Vec3(-1.0f) : a.texels[a.textures[size_t(t)].offset];
}

TEST(Flatten, PathDecodesEightBitColourTexturesFromSrgb) {
    const SceneArrays a = flatten(TexturedScene(IntegratorKind::Path).scene).arrays;
    EXPECT_NEAR(firstTexel(a, 0, kDiffuseTexture).x, TexturedScene::kDecoded, 1e-5f);
    for (int slot : {kSpecularTexture, kEmissiveTexture})
        EXPECT_NEAR(firstTexel(a, 1, slot).x, TexturedScene::kDecoded, 1e-5f);
    // The other texel: 0 stays 0, 1 stays 1, 0.5 decodes to 0.214 (the channels are decoded one by one).
    const int32_t decoded = a.materials[0].textures[kDiffuseTexture];
    const Vec3 second = a.texels[a.textures[size_t(decoded)].offset + 1];
    EXPECT_EQ(second.x, 0.0f);
    EXPECT_NEAR(second.y, 0.21404f, 1e-5f);
    EXPECT_NEAR(second.z, 1.0f, 1e-6f);
    // The normal map and the float image are untouched: the 8-bit image is stored twice, the float one once.
    EXPECT_EQ(firstTexel(a, 0, kNormalTexture).x, TexturedScene::kEncoded);
    EXPECT_EQ(firstTexel(a, 1, kDiffuseTexture).x, TexturedScene::kEncoded);
    EXPECT_NE(a.materials[0].textures[kNormalTexture], decoded);
    EXPECT_EQ(a.materials[1].textures[kSpecularTexture], decoded);  // one decoded copy shared by the colour slots
    EXPECT_EQ(a.textures.size(), 3u);
    EXPECT_EQ(a.texels.size(), 6u);
}

TEST(Flatten, ThesisKeepsEveryTextureAsStored) {
    const SceneArrays a = flatten(TexturedScene(IntegratorKind::Thesis).scene).arrays;
    for (int slot : {kDiffuseTexture, kNormalTexture}) EXPECT_EQ(firstTexel(a, 0, slot).x, TexturedScene::kEncoded);
    for (int slot : {kSpecularTexture, kEmissiveTexture, kDiffuseTexture})
        EXPECT_EQ(firstTexel(a, 1, slot).x, TexturedScene::kEncoded);
    EXPECT_EQ(a.materials[0].textures[kNormalTexture], a.materials[0].textures[kDiffuseTexture]);  // one copy
    EXPECT_EQ(a.textures.size(), 2u);
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
