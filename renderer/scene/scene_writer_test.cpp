// Round trip of the scene writer: read a scene, write it, read the text back, and get the same scene
// (every field, transforms in order, texture and material references, files found again).
#include "scene/scene_writer.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "scene/scene_reader.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace trazo {
namespace {

std::string listed(const Diagnostics& d) { return test::listedDiagnostics(d, true); }

// Bit-for-bit equality of floats (the writer prints enough digits for it).
bool same(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same(Vec3 a, Vec3 b) { return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z); }
bool sameFile(const std::string& a, const std::string& b) { return std::filesystem::equivalent(a, b); }

void expectSameTransforms(const std::vector<TransformStep>& a, const std::vector<TransformStep>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].kind, b[i].kind) << i;
        EXPECT_TRUE(same(a[i].value, b[i].value)) << i;
        EXPECT_TRUE(same(a[i].angle, b[i].angle)) << i;
    }
}

// What the file of a CSG or mesh object gave: its tree's node count, its mesh's corner count; -1 when not read.
long partCount(const Csg& c) { return c.tree ? long(c.tree->nodes.size()) : -1; }
long partCount(const Mesh& m) { return m.data ? long(m.data->corners.size()) : -1; }

template <class Object>
void expectSameFileObjects(const std::vector<Object>& a, const std::vector<Object>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].material, b[i].material);
        EXPECT_TRUE(sameFile(a[i].source, b[i].source));
        expectSameTransforms(a[i].transforms, b[i].transforms);
        ASSERT_GE(partCount(b[i]), 0);
        EXPECT_EQ(partCount(a[i]), partCount(b[i]));
    }
}

void expectSameScene(const Scene& a, const Scene& b) {
    EXPECT_TRUE(same(a.settings.backgroundColor, b.settings.backgroundColor));
    EXPECT_EQ(a.settings.renderWidth, b.settings.renderWidth);
    EXPECT_EQ(a.settings.renderHeight, b.settings.renderHeight);
    EXPECT_EQ(a.settings.reflectionQuality, b.settings.reflectionQuality);
    EXPECT_EQ(a.settings.reflectionSteps, b.settings.reflectionSteps);
    EXPECT_EQ(a.settings.indirectQuality, b.settings.indirectQuality);
    EXPECT_TRUE(same(a.settings.colorBleeding, b.settings.colorBleeding));
    EXPECT_EQ(a.settings.antialiasing, b.settings.antialiasing);
    EXPECT_TRUE(same(a.camera.pov, b.camera.pov));
    EXPECT_TRUE(same(a.camera.poi, b.camera.poi));
    EXPECT_TRUE(same(a.camera.fovDegrees, b.camera.fovDegrees));

    ASSERT_EQ(a.textures.size(), b.textures.size());
    for (size_t i = 0; i < a.textures.size(); ++i) {
        EXPECT_EQ(a.textures[i].name, b.textures[i].name);
        EXPECT_TRUE(sameFile(a.textures[i].source, b.textures[i].source));
    }
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (size_t i = 0; i < a.materials.size(); ++i) {
        const Material &x = a.materials[i], &y = b.materials[i];
        EXPECT_EQ(x.name, y.name);
#define TRAZO_X(Type, field, ...) EXPECT_TRUE(same(x.field, y.field)) << x.name << " " #field;
#define TRAZO_NO_SLOTS()
        TRAZO_MATERIAL_FIELDS(TRAZO_X, TRAZO_NO_SLOTS)
#undef TRAZO_NO_SLOTS
#undef TRAZO_X
        EXPECT_EQ(x.textures, y.textures);
    }
    ASSERT_EQ(a.spheres.size(), b.spheres.size());
    for (size_t i = 0; i < a.spheres.size(); ++i) {
        EXPECT_EQ(a.spheres[i].material, b.spheres[i].material);
        EXPECT_TRUE(same(a.spheres[i].center, b.spheres[i].center) && same(a.spheres[i].radius, b.spheres[i].radius));
    }
    ASSERT_EQ(a.boxes.size(), b.boxes.size());
    for (size_t i = 0; i < a.boxes.size(); ++i) {
        EXPECT_EQ(a.boxes[i].material, b.boxes[i].material);
        expectSameTransforms(a.boxes[i].transforms, b.boxes[i].transforms);
    }
    ASSERT_EQ(a.cylinders.size(), b.cylinders.size());
    for (size_t i = 0; i < a.cylinders.size(); ++i) {
        const Cylinder &x = a.cylinders[i], &y = b.cylinders[i];
        EXPECT_EQ(x.material, y.material);
        EXPECT_TRUE(same(x.base, y.base) && same(x.axis, y.axis) && same(x.height, y.height) && same(x.radius, y.radius));
    }
    expectSameFileObjects(a.csgs, b.csgs);
    expectSameFileObjects(a.meshes, b.meshes);
    ASSERT_EQ(a.pointLights.size(), b.pointLights.size());
    for (size_t i = 0; i < a.pointLights.size(); ++i) {
        EXPECT_TRUE(same(a.pointLights[i].position, b.pointLights[i].position));
        EXPECT_TRUE(same(a.pointLights[i].color, b.pointLights[i].color));
    }
    ASSERT_EQ(a.areaLights.size(), b.areaLights.size());
    for (size_t i = 0; i < a.areaLights.size(); ++i) {
        const AreaLight &x = a.areaLights[i], &y = b.areaLights[i];
        EXPECT_TRUE(same(x.color, y.color) && same(x.position, y.position) && same(x.direction, y.direction));
        EXPECT_TRUE(same(x.rollAngle, y.rollAngle) && same(x.width, y.width) && same(x.height, y.height));
        EXPECT_EQ(x.subdivisionX, y.subdivisionX);
        EXPECT_EQ(x.subdivisionY, y.subdivisionY);
    }
}

// write → read in another folder → same scene; and writing that again gives the same text.
void roundTrip(const Scene& original, const std::string& outPath) {
    std::string error;
    ASSERT_TRUE(writeSceneFile(original, outPath, error)) << error;
    Diagnostics diags;
    const Scene back = readSceneFile(outPath, diags);
    ASSERT_FALSE(diags.hasErrors()) << listed(diags) << formatScene(original, outPath);
    expectSameScene(original, back);
    EXPECT_EQ(formatScene(original, outPath), formatScene(back, outPath));
}

class SceneWriterSeed : public ::testing::TestWithParam<const char*> {};

TEST_P(SceneWriterSeed, RoundTripGivesTheSameScene) {
    Diagnostics diags;
    const Scene original = readSceneFile(test::sourcePath(std::string("scenes/") + GetParam()), diags);
    ASSERT_FALSE(diags.hasErrors()) << listed(diags);
    std::filesystem::create_directories(test::tempPath("writer"));
    roundTrip(original, test::tempPath("writer") + "/" + GetParam());
}

INSTANTIATE_TEST_SUITE_P(SeedScenes, SceneWriterSeed,
                         ::testing::Values("scene1_area.scene", "scene3_csg.scene", "scene6_glossy.scene",
                                           "scene7_refract.scene", "scene8_textured_mesh.scene"));

TEST(SceneWriter, EditedFieldsAndAwkwardValuesSurvive) {
    Diagnostics diags;
    Scene scene = readSceneText(
        "Material {\n Name glass\n}\nSphere {\n}\nBox {\n Material glass\n Scale 1 2 3\n Rotation 0 1 0 0.3\n"
        " Translation 1 0 0\n Rotation 1 1 0 -1e-7\n}\nCylinder {\n Material glass\n}\nPointLight {\n}\n",
        test::tempPath("edited") + "/in.scene", diags);
    ASSERT_FALSE(diags.hasErrors()) << listed(diags);
    scene.settings.backgroundColor = Vec3(0.1f, 1e-20f, 1e12f);  // 1e12: the largest colour the reader takes
    scene.spheres[0].center = Vec3(0.0f, -3.4e38f, 1e-30f);
    scene.settings.antialiasing = 16;
    scene.camera.fovDegrees = 33.333333f;
    scene.materials[0].opacity = 0.1f;
    scene.materials[0].reflectionAmount = 1.0f / 3.0f;
    scene.areaLights.push_back(AreaLight{});
    scene.areaLights[0].rollAngle = -0.7f;
    scene.areaLights[0].subdivisionX = 7;
    std::filesystem::create_directories(test::tempPath("edited-out"));
    roundTrip(scene, test::tempPath("edited-out") + "/out.scene");
}

TEST(SceneWriter, UnwritableFolderFailsWithAReason) {
    std::string error;
    EXPECT_FALSE(writeSceneFile(Scene{}, test::tempPath("missing-folder") + "/x/y.scene", error));
    EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace trazo
