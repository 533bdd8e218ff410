// Tests of the scene reader: every block and parameter, defaults, synonyms, transforms, names, paths,
// every SPEC §2 error with its line, and the seed scenes.
#include "scene/scene_reader.h"

#include <FreeImage.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "flatten/flatten.h"
#include "fetched_assets.h"
#include "scene/csg_reader.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace trazo {
namespace {

struct Result {
    Scene scene;
    Diagnostics diags;
};

Result readText(const std::string& text, const std::string& path = "t.scene") {
    Result r;
    r.scene = readSceneText(text, path, r.diags);
    return r;
}

std::string listed(const Diagnostics& d, bool errorsOnly = false) { return test::listedDiagnostics(d, errorsOnly); }

void expectVec(Vec3 v, float x, float y, float z) {
    EXPECT_FLOAT_EQ(v.x, x);
    EXPECT_FLOAT_EQ(v.y, y);
    EXPECT_FLOAT_EQ(v.z, z);
}
void expectVec(Vec3 v, Vec3 want) { expectVec(v, want.x, want.y, want.z); }

// What a scene file sets in each block, field by field (where it was written aside), and the checks of a block
// as read against them.
struct SettingsValues {
    Vec3 background;
    int width, height, reflectionQuality, reflectionSteps, indirectQuality;
    float colorBleeding;
    int antialiasing;
};

void expectSettings(const SceneSettings& got, const SettingsValues& want) {
    expectVec(got.backgroundColor, want.background);
    EXPECT_EQ(got.renderWidth, want.width);
    EXPECT_EQ(got.renderHeight, want.height);
    EXPECT_EQ(got.reflectionQuality, want.reflectionQuality);
    EXPECT_EQ(got.reflectionSteps, want.reflectionSteps);
    EXPECT_EQ(got.indirectQuality, want.indirectQuality);
    EXPECT_FLOAT_EQ(got.colorBleeding, want.colorBleeding);
    EXPECT_EQ(got.antialiasing, want.antialiasing);
}

struct CameraValues {
    Vec3 pov, poi;
    float fov;
};

void expectCamera(const Camera& got, const CameraValues& want) {
    expectVec(got.pov, want.pov);
    expectVec(got.poi, want.poi);
    EXPECT_FLOAT_EQ(got.fovDegrees, want.fov);
}

// The thesis's Material parameters but Name and the textures.
struct MaterialValues {
    Vec3 diffuse, specular, emissive;
    float roughness, opacity, refractionIndex, reflectionAngleDegrees, reflectionAmount;
};

void expectMaterial(const Material& got, const MaterialValues& want) {
    expectVec(got.diffuseColor, want.diffuse);
    expectVec(got.specularColor, want.specular);
    expectVec(got.emissiveColor, want.emissive);
    EXPECT_FLOAT_EQ(got.roughness, want.roughness);
    EXPECT_FLOAT_EQ(got.opacity, want.opacity);
    EXPECT_FLOAT_EQ(got.refractionIndex, want.refractionIndex);
    EXPECT_FLOAT_EQ(got.reflectionAngleDegrees, want.reflectionAngleDegrees);
    EXPECT_FLOAT_EQ(got.reflectionAmount, want.reflectionAmount);
}

struct SphereValues {
    int32_t material;
    Vec3 center;
    float radius;
};

void expectSphere(const Sphere& got, const SphereValues& want) {
    EXPECT_EQ(got.material, want.material);
    expectVec(got.center, want.center);
    EXPECT_FLOAT_EQ(got.radius, want.radius);
}

struct CylinderValues {
    int32_t material;
    Vec3 base, axis;
    float height, radius;
};

void expectCylinder(const Cylinder& got, const CylinderValues& want) {
    EXPECT_EQ(got.material, want.material);
    expectVec(got.base, want.base);
    expectVec(got.axis, want.axis);
    EXPECT_FLOAT_EQ(got.height, want.height);
    EXPECT_FLOAT_EQ(got.radius, want.radius);
}

struct AreaLightValues {
    Vec3 color, position, direction;
    float rollAngle, width, height;
    int subdivisionX, subdivisionY;
};

void expectAreaLight(const AreaLight& got, const AreaLightValues& want) {
    expectVec(got.color, want.color);
    expectVec(got.position, want.position);
    expectVec(got.direction, want.direction);
    EXPECT_FLOAT_EQ(got.rollAngle, want.rollAngle);
    EXPECT_FLOAT_EQ(got.width, want.width);
    EXPECT_FLOAT_EQ(got.height, want.height);
    EXPECT_EQ(got.subdivisionX, want.subdivisionX);
    EXPECT_EQ(got.subdivisionY, want.subdivisionY);
}

void expectTransform(const TransformStep& got, TransformStep::Kind kind, Vec3 value) {
    EXPECT_EQ(got.kind, kind);
    expectVec(got.value, value);
}

void writeFile(const std::string& path, const std::string& text) {
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    std::ofstream(path) << text;
}

void writePng(const std::string& path) {
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    FIBITMAP* bm = FreeImage_Allocate(2, 2, 24);
    ASSERT_TRUE(FreeImage_Save(FIF_PNG, bm, path.c_str(), 0));
    FreeImage_Unload(bm);
}

const char* const kTriangleWithUvs = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";
const char* const kTinyCsg = "Sphere {\n}\nBox {\n}\nUnion {\n LeftType Sphere\n LeftIndex 0\n RightType Box\n RightIndex 0\n}\n";

// Every block with every thesis parameter given (textures a.png and b.png, t.obj and t.csg beside it).
const char* const kEveryParameterScene = R"(SceneSettings
{
    BackgroundColor 0.1 0.2 0.3
    RenderWidth 640
    RenderHeight 480
    ReflectionQuality 2
    ReflectionSteps 4
    IndirectQuality 5
    ColorBleeding 2.5
    Antialiasing 16
}
Camera
{
    POV 1 2 3
    POI 4 5 6
    FOV 30
}
Texture
{
    Name texA
    Source "a.png"
}
Texture
{
    Name texB
    Source "b.png"
}
Material
{
    Name m
    DiffuseColor 0.1 0.2 0.3
    SpecularColor 0.4 0.5 0.6
    EmissiveColor 0.7 0.8 0.9
    DiffuseTexture texA
    SpecularTexture texB
    EmissiveTexture texA
    NormalTexture texB
    Roughness 0.25
    Opacity 0.75
    RefractionIndex 1.5
    ReflectionAngle 30
    ReflectionAmount 0.6
}
Sphere
{
    Material m
    Center 1 2 3
    Radius 4
}
Box
{
    Material m
    Translation 1 2 3
    Rotation 0 1 0 0.5
    Scale 2 3 4
}
Cylinder
{
    Material m
    Base 1 2 3
    Axis 1 0 0
    Height 5
    Radius 0.5
}
CSG
{
    Material m
    Source "t.csg"
    Translation 0 1 0
    Rotation 1 0 0 0.25
    Scale 2 2 2
}
Mesh
{
    Material m
    Source "t.obj"
    Scale 3 3 3
    Rotation 0 0 1 1.5
    Translation 7 8 9
}
PointLight
{
    Position 1 2 3
    Color 0.5 0.6 0.7
}
AreaLight
{
    Color 0.1 0.2 0.3
    Position 4 5 6
    Direction 0 0 -1
    RollAngle 0.5
    Width 2
    Height 3
    Subdivision 4 6
}
)";

// kEveryParameterScene's textures and its material, read from `dir`.
void expectEveryTextureAndMaterial(const Scene& s, const std::string& dir) {
    ASSERT_EQ(s.textures.size(), 2u);
    EXPECT_EQ(s.textures[0].name, "texA");
    EXPECT_EQ(s.textures[0].source, dir + "/a.png");
    ASSERT_TRUE(s.textures[0].image);
    EXPECT_EQ(s.textures[0].image->width, 2);
    EXPECT_EQ(s.textures[0].where.line, 18);
    EXPECT_EQ(s.textures[1].name, "texB");

    ASSERT_EQ(s.materials.size(), 1u);
    const Material& m = s.materials[0];
    EXPECT_EQ(m.name, "m");
    expectMaterial(m, {.diffuse = {0.1f, 0.2f, 0.3f}, .specular = {0.4f, 0.5f, 0.6f}, .emissive = {0.7f, 0.8f, 0.9f},
                       .roughness = 0.25f, .opacity = 0.75f, .refractionIndex = 1.5f, .reflectionAngleDegrees = 30,
                       .reflectionAmount = 0.6f});
    EXPECT_EQ(m.textures[kDiffuseTexture], 0);
    EXPECT_EQ(m.textures[kSpecularTexture], 1);
    EXPECT_EQ(m.textures[kEmissiveTexture], 0);
    EXPECT_EQ(m.textures[kNormalTexture], 1);
    EXPECT_EQ(m.where.line, 28);
}

// kEveryParameterScene's objects, the file `scene` read from `dir`.
void expectEveryObject(const Scene& s, const std::string& dir, const std::string& scene) {
    using Kind = TransformStep::Kind;
    ASSERT_EQ(s.spheres.size(), 1u);
    expectSphere(s.spheres[0], {.material = 0, .center = {1, 2, 3}, .radius = 4});
    EXPECT_EQ(s.spheres[0].where.line, 44);
    EXPECT_EQ(s.spheres[0].where.file, scene);

    ASSERT_EQ(s.boxes.size(), 1u);
    EXPECT_EQ(s.boxes[0].material, 0);
    ASSERT_EQ(s.boxes[0].transforms.size(), 3u);
    expectTransform(s.boxes[0].transforms[0], Kind::Translation, {1, 2, 3});
    expectTransform(s.boxes[0].transforms[1], Kind::Rotation, {0, 1, 0});
    EXPECT_FLOAT_EQ(s.boxes[0].transforms[1].angle, 0.5f);
    expectTransform(s.boxes[0].transforms[2], Kind::Scale, {2, 3, 4});

    ASSERT_EQ(s.cylinders.size(), 1u);
    expectCylinder(s.cylinders[0], {.material = 0, .base = {1, 2, 3}, .axis = {1, 0, 0}, .height = 5, .radius = 0.5f});

    ASSERT_EQ(s.csgs.size(), 1u);
    EXPECT_EQ(s.csgs[0].material, 0);
    EXPECT_EQ(s.csgs[0].source, dir + "/t.csg");
    ASSERT_TRUE(s.csgs[0].tree);
    EXPECT_EQ(s.csgs[0].tree->nodes.size(), 3u);
    EXPECT_EQ(s.csgs[0].tree->root, 2);
    ASSERT_EQ(s.csgs[0].transforms.size(), 3u);
    EXPECT_FLOAT_EQ(s.csgs[0].transforms[1].angle, 0.25f);

    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].material, 0);
    EXPECT_EQ(s.meshes[0].source, dir + "/t.obj");
    ASSERT_TRUE(s.meshes[0].data);
    EXPECT_EQ(s.meshes[0].data->corners.size(), 3u);
    ASSERT_EQ(s.meshes[0].transforms.size(), 3u);
    EXPECT_EQ(s.meshes[0].transforms[0].kind, Kind::Scale);
    EXPECT_EQ(s.meshes[0].transforms[2].kind, Kind::Translation);
}

TEST(SceneReader, EveryParameterReachesItsField) {
    const std::string dir = test::tempPath("every");
    writePng(dir + "/a.png");
    writePng(dir + "/b.png");
    writeFile(dir + "/t.obj", kTriangleWithUvs);
    writeFile(dir + "/t.csg", kTinyCsg);
    const std::string scene = dir + "/every.scene";
    writeFile(scene, kEveryParameterScene);
    Diagnostics diags;
    const Scene s = readSceneFile(scene, diags);
    ASSERT_TRUE(diags.items.empty()) << listed(diags);
    EXPECT_EQ(s.path, scene);
    expectSettings(s.settings, {.background = {0.1f, 0.2f, 0.3f}, .width = 640, .height = 480, .reflectionQuality = 2,
                                .reflectionSteps = 4, .indirectQuality = 5, .colorBleeding = 2.5f, .antialiasing = 16});
    expectCamera(s.camera, {.pov = {1, 2, 3}, .poi = {4, 5, 6}, .fov = 30});
    expectEveryTextureAndMaterial(s, dir);
    expectEveryObject(s, dir, scene);
    ASSERT_EQ(s.pointLights.size(), 1u);
    expectVec(s.pointLights[0].position, 1, 2, 3);
    expectVec(s.pointLights[0].color, 0.5f, 0.6f, 0.7f);
    ASSERT_EQ(s.areaLights.size(), 1u);
    expectAreaLight(s.areaLights[0], {.color = {0.1f, 0.2f, 0.3f}, .position = {4, 5, 6}, .direction = {0, 0, -1},
                                      .rollAngle = 0.5f, .width = 2, .height = 3, .subdivisionX = 4,
                                      .subdivisionY = 6});
}

TEST(SceneReader, EmptyBlocksTakeTheSpecDefaults) {
    const Result r = readText(
        "SceneSettings {\n}\nCamera {\n}\nMaterial {\n Name m\n}\nSphere {\n}\nBox {\n}\nCylinder {\n}\n"
        "PointLight {\n}\nAreaLight {\n}\n");
    EXPECT_FALSE(r.diags.hasErrors()) << listed(r.diags);
    const Scene& s = r.scene;
    expectSettings(s.settings, {.background = {0, 0, 0}, .width = 512, .height = 512, .reflectionQuality = 3,
                                .reflectionSteps = 1, .indirectQuality = 3, .colorBleeding = 1.0f, .antialiasing = 1});
    expectCamera(s.camera, {.pov = {0, 0, 10}, .poi = {0, 0, 0}, .fov = 45});
    ASSERT_EQ(s.materials.size(), 1u);
    expectMaterial(s.materials[0], {.diffuse = {0.9f, 0.9f, 0.9f}, .specular = {0.8f, 0.8f, 0.8f},
                                    .emissive = {0, 0, 0}, .roughness = 0.5f, .opacity = 1, .refractionIndex = 1,
                                    .reflectionAngleDegrees = 0, .reflectionAmount = 0});
    EXPECT_EQ(s.materials[0].textures, noTextures());
    ASSERT_EQ(s.spheres.size(), 1u);
    expectSphere(s.spheres[0], {.material = kDefaultMaterial, .center = {0, 0, 0}, .radius = 1});
    ASSERT_EQ(s.boxes.size(), 1u);
    EXPECT_TRUE(s.boxes[0].transforms.empty());
    ASSERT_EQ(s.cylinders.size(), 1u);
    expectCylinder(s.cylinders[0],
                   {.material = kDefaultMaterial, .base = {0, 0, 0}, .axis = {0, 1, 0}, .height = 1, .radius = 1});
    ASSERT_EQ(s.pointLights.size(), 1u);
    expectVec(s.pointLights[0].position, 0, 0, 0);
    expectVec(s.pointLights[0].color, 1, 1, 1);
    ASSERT_EQ(s.areaLights.size(), 1u);
    expectAreaLight(s.areaLights[0], {.color = {1, 1, 1}, .position = {0, 0, 0}, .direction = {0, -1, 0},
                                      .rollAngle = 0, .width = 1, .height = 1, .subdivisionX = 5, .subdivisionY = 5});
}

TEST(SceneReader, AnEmptyFileIsTheDefaultScene) {
    const Result r = readText("# nothing here\n\n");
    EXPECT_TRUE(r.diags.items.empty());
    EXPECT_EQ(r.scene.settings.renderWidth, 512);
    EXPECT_FLOAT_EQ(r.scene.camera.pov.z, 10);
}

TEST(SceneReader, TwoWordSynonyms) {
    const Result r = readText(
        "Material {\n Name m\n Reflection Angle 30\n Reflection Amount 0.5\n}\nAreaLight {\n Roll Angle 0.25\n}\n");
    EXPECT_TRUE(r.diags.items.empty()) << listed(r.diags);
    ASSERT_EQ(r.scene.materials.size(), 1u);
    EXPECT_FLOAT_EQ(r.scene.materials[0].reflectionAngleDegrees, 30);
    EXPECT_FLOAT_EQ(r.scene.materials[0].reflectionAmount, 0.5f);
    ASSERT_EQ(r.scene.areaLights.size(), 1u);
    EXPECT_FLOAT_EQ(r.scene.areaLights[0].rollAngle, 0.25f);
}

TEST(SceneReader, LaterValueWins) {
    const Result r = readText("Sphere {\n Radius 1\n Center 1 1 1\n Radius 2\n}\n");
    ASSERT_EQ(r.scene.spheres.size(), 1u);
    EXPECT_FLOAT_EQ(r.scene.spheres[0].radius, 2);
}

TEST(SceneReader, LastCameraWinsAndStartsFromTheDefaults) {
    const Result r = readText("Camera {\n POV 1 1 1\n FOV 30\n}\nCamera {\n POI 0 1 0\n}\n");
    EXPECT_TRUE(r.diags.items.empty());
    expectVec(r.scene.camera.pov, 0, 0, 10);
    expectVec(r.scene.camera.poi, 0, 1, 0);
    EXPECT_FLOAT_EQ(r.scene.camera.fovDegrees, 45);
}

TEST(SceneReader, TransformsAccumulateInWrittenOrder) {
    const Result r = readText(
        "Box {\n Scale 2 2 2\n Translation 1 0 0\n}\n"
        "Box {\n Translation 1 0 0\n Scale 2 2 2\n}\n"
        "Box {\n Rotation 0 1 0 1.5707963\n Translation 0 0 5\n}\n");
    ASSERT_EQ(r.scene.boxes.size(), 3u);
    const Vec3 p{1, 0, 0};
    // Later steps act on the result of earlier ones.
    const Vec3 scaledThenMoved = composeTransforms(r.scene.boxes[0].transforms).applyToPoint(p);
    const Vec3 movedThenScaled = composeTransforms(r.scene.boxes[1].transforms).applyToPoint(p);
    expectVec(scaledThenMoved, 3, 0, 0);
    expectVec(movedThenScaled, 4, 0, 0);
    const Vec3 turned = composeTransforms(r.scene.boxes[2].transforms).applyToPoint(p);  // +X → −Z, then +5 Z
    EXPECT_NEAR(turned.x, 0, 1e-6);
    EXPECT_NEAR(turned.y, 0, 1e-6);
    EXPECT_NEAR(turned.z, 4, 1e-6);
    EXPECT_EQ(composeTransforms({}).applyToPoint(p).x, 1.0f);
}

TEST(SceneReader, NamesResolveToIndicesInFileOrder) {
    const Result r = readText(
        "Material {\n Name a\n}\nMaterial {\n Name b\n}\nSphere {\n Material b\n}\nSphere {\n Material a\n}\n");
    EXPECT_TRUE(r.diags.items.empty()) << listed(r.diags);
    ASSERT_EQ(r.scene.spheres.size(), 2u);
    EXPECT_EQ(r.scene.spheres[0].material, 1);
    EXPECT_EQ(r.scene.spheres[1].material, 0);
}

TEST(SceneReader, AntialiasingOtherThan1_4_16IsAWarningAndFallsBackTo1) {
    const Result r = readText("SceneSettings {\n Antialiasing 3\n}\n");
    EXPECT_FALSE(r.diags.hasErrors());
    EXPECT_EQ(listed(r.diags), "t.scene:2:15: warning: Antialiasing must be 1, 4 or 16, got 3; using 1\n");
    EXPECT_EQ(r.scene.settings.antialiasing, 1);
    for (int ok : {1, 4, 16}) {
        const Result good = readText("SceneSettings {\n Antialiasing " + std::to_string(ok) + "\n}\n");
        EXPECT_TRUE(good.diags.items.empty());
        EXPECT_EQ(good.scene.settings.antialiasing, ok);
    }
}

TEST(SceneReader, ObjectsWithoutMaterialGetTheDefaultAndOneWarningEach) {
    const std::string dir = test::tempPath("defaultmat");
    writeFile(dir + "/t.obj", kTriangleWithUvs);
    writeFile(dir + "/t.csg", kTinyCsg);
    Result r;
    r.scene = readSceneText("Sphere {\n}\nBox {\n}\nCylinder {\n}\nMesh {\n Source \"t.obj\"\n}\nCSG {\n Source \"t.csg\"\n}\n"
                            "PointLight {\n}\n",
                            dir + "/d.scene", r.diags);
    EXPECT_FALSE(r.diags.hasErrors()) << listed(r.diags);
    EXPECT_EQ(listed(r.diags), dir + "/d.scene:1: warning: Sphere has no Material; using the default material\n" +
                                   dir + "/d.scene:3: warning: Box has no Material; using the default material\n" +
                                   dir + "/d.scene:5: warning: Cylinder has no Material; using the default material\n" +
                                   dir + "/d.scene:7: warning: Mesh has no Material; using the default material\n" +
                                   dir + "/d.scene:10: warning: CSG has no Material; using the default material\n");
    EXPECT_EQ(r.scene.spheres[0].material, kDefaultMaterial);
    EXPECT_EQ(r.scene.boxes[0].material, kDefaultMaterial);
    EXPECT_EQ(r.scene.cylinders[0].material, kDefaultMaterial);
    EXPECT_EQ(r.scene.meshes[0].material, kDefaultMaterial);
    EXPECT_EQ(r.scene.csgs[0].material, kDefaultMaterial);
}

TEST(SceneReader, RelativePathsResolveAgainstTheNamingFile) {
    const std::string dir = test::tempPath("relative");
    writePng(dir + "/scenes/assets/tex.png");
    writeFile(dir + "/scenes/assets/tri.obj", kTriangleWithUvs);
    writeFile(dir + "/scenes/tree.csg", kTinyCsg);
    writeFile(dir + "/scenes/r.scene",
              "Texture {\n Name t\n Source \"assets/tex.png\"\n}\n"
              "Material {\n Name m\n DiffuseTexture t\n}\n"
              "Mesh {\n Material m\n Source \"assets/tri.obj\"\n}\n"
              "CSG {\n Material m\n Source \"tree.csg\"\n}\n");
    // Read from another working folder: the paths must not depend on it.
    Diagnostics diags;
    const Scene s = readSceneFile(dir + "/scenes/r.scene", diags);
    ASSERT_TRUE(diags.items.empty()) << listed(diags);
    EXPECT_EQ(s.textures.at(0).source, dir + "/scenes/assets/tex.png");
    EXPECT_TRUE(s.textures.at(0).image);
    EXPECT_EQ(s.meshes.at(0).source, dir + "/scenes/assets/tri.obj");
    EXPECT_TRUE(s.meshes.at(0).data);
    EXPECT_EQ(s.csgs.at(0).source, dir + "/scenes/tree.csg");
    EXPECT_TRUE(s.csgs.at(0).tree);
}

// The warning comes from flatten(), once per object at its block's line, in the order of the kinds; the reader
// has nothing to say about it.
TEST(SceneReader, ObjectsWithoutUvsAreWarnedOnceWhenTheirMaterialHasTextures) {
    const std::string dir = test::tempPath("nouvs");
    writePng(dir + "/tex.png");
    writeFile(dir + "/plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    writeFile(dir + "/tree.csg", kTinyCsg);
    Result r;
    r.scene = readSceneText(
        "Texture {\n Name t\n Source \"tex.png\"\n}\nMaterial {\n Name m\n DiffuseTexture t\n NormalTexture t\n}\n"
        "Mesh {\n Material m\n Source \"plain.obj\"\n}\nCSG {\n Material m\n Source \"tree.csg\"\n}\n"
        "Sphere {\n Material m\n}\n",
        dir + "/u.scene", r.diags);
    EXPECT_EQ(listed(r.diags), "");
    const FlattenResult flat = flatten(r.scene);
    EXPECT_EQ(listed(flat.warnings), dir + "/u.scene:14: warning: CSG '" + dir +
                                         "/tree.csg' has no texture coordinates; the textures of material 'm' are "
                                         "ignored for it\n" + dir + "/u.scene:10: warning: Mesh '" + dir +
                                         "/plain.obj' has no texture coordinates; the textures of material 'm' are "
                                         "ignored for it\n");
}

TEST(SceneReader, ErrorsInsideNamedFilesCarryTheirOwnFileAndLine) {
    const std::string dir = test::tempPath("inner");
    writeFile(dir + "/bad.obj", "v 0 0 0\nv 1 0 zero\nv 0 1 0\nf 1 2 3\n");
    writeFile(dir + "/bad.csg", "Sphere {\n Radius -2\n}\n");
    Result r;
    r.scene = readSceneText("Mesh {\n Source \"bad.obj\"\n}\nCSG {\n Source \"bad.csg\"\n}\n", dir + "/i.scene", r.diags);
    const std::string errors = listed(r.diags, true);
    EXPECT_NE(errors.find(dir + "/bad.obj:2:7: error: 'zero' is not a finite number\n"), std::string::npos) << errors;
    EXPECT_NE(errors.find(dir + "/bad.csg:2:9: error: Radius must be positive, got -2\n"), std::string::npos) << errors;
}

TEST(SceneReader, AllErrorsOfAFileAreCollected) {
    const Result r = readText("Sphere {\n Radius -1\n Centre 0 0 0\n}\nBox {\n Scale 0 1 1\n}\nFoo {\n}\n");
    EXPECT_EQ(listed(r.diags, true),
              "t.scene:2:9: error: Radius must be positive, got -1\n"
              "t.scene:3: error: unknown parameter 'Centre' in Sphere (did you mean 'Center'?)\n"
              "t.scene:6:8: error: Scale component must not be zero (a singular transform)\n"
              "t.scene:8: error: unknown block 'Foo' (did you mean 'Box'?)\n");
}

TEST(SceneReader, OneMistakeGivesOneError) {
    // A Source with a bad value still counts as given: no second "missing Source" error.
    const Result r = readText("Mesh {\n Material m\n Source a.obj\n}\nMaterial {\n Name m\n}\n");
    EXPECT_EQ(listed(r.diags, true),
              "t.scene:3:9: error: Source: expected a path in double quotes, got 'a.obj' (write \"a.obj\")\n"
              "t.scene:2: error: material 'm' is used before it is declared (at line 6)\n");
}

TEST(SceneReader, UnreadableSceneFileNamesPathAndReason) {
    Diagnostics diags;
    readSceneFile("/nonexistent/trazo/x.scene", diags);
    EXPECT_EQ(listed(diags), "/nonexistent/trazo/x.scene: error: cannot read scene file: No such file or directory\n");
}

TEST(SceneReader, IntegerParametersRejectFractions) {
    const std::pair<const char*, const char*> cases[] = {
        {"SceneSettings", "RenderWidth 1.5"},     {"SceneSettings", "RenderHeight 2.5"},
        {"SceneSettings", "ReflectionQuality 1.5"}, {"SceneSettings", "ReflectionSteps 1.5"},
        {"SceneSettings", "IndirectQuality 1e1"}, {"SceneSettings", "Antialiasing 4.0"},
        {"AreaLight", "Subdivision 5 5.5"},
    };
    for (const auto& [block, line] : cases) {
        const Result r = readText(std::string(block) + " {\n " + line + "\n}\n");
        const std::string errors = listed(r.diags, true);
        const std::string name = std::string(line).substr(0, std::string(line).find(' '));
        EXPECT_NE(errors.find("t.scene:2:"), std::string::npos) << line;
        EXPECT_NE(errors.find(name + ": expected an integer, got '"), std::string::npos) << errors;
    }
}

// Each case: a scene text and one error it must produce, formatted exactly (file:line[:column]).
struct BadScene {
    const char* name;
    std::string text;
    std::string expected;
};

class SceneReaderError : public ::testing::TestWithParam<BadScene> {};

TEST_P(SceneReaderError, ReportsTheLine) {
    const Result r = readText(GetParam().text);
    EXPECT_TRUE(r.diags.hasErrors());
    const std::string errors = listed(r.diags, true);
    EXPECT_NE(errors.find(GetParam().expected + "\n"), std::string::npos) << errors;
}

INSTANTIATE_TEST_SUITE_P(
    Spec2, SceneReaderError,
    ::testing::Values(
        BadScene{"UnknownBlock", "Spher {\n}\n", "t.scene:1: error: unknown block 'Spher' (did you mean 'Sphere'?)"},
        BadScene{"UnknownParameter", "Sphere {\n Radus 2\n}\n",
                 "t.scene:2: error: unknown parameter 'Radus' in Sphere (did you mean 'Radius'?)"},
        BadScene{"TooFewValues", "Sphere {\n Center 1 2\n}\n", "t.scene:2: error: Center takes 3 numbers, got 2"},
        BadScene{"TooManyValues", "Sphere {\n Radius 1 2\n}\n", "t.scene:2: error: Radius takes 1 number, got 2"},
        BadScene{"SynonymWithoutValue", "Material {\n Name m\n Reflection Angle\n}\n",
                 "t.scene:3: error: ReflectionAngle takes 1 number, got 0"},
        BadScene{"NameForNumber", "Sphere {\n Radius big\n}\n",
                 "t.scene:2:9: error: Radius: expected a number, got 'big'"},
        BadScene{"RealForInt", "SceneSettings {\n RenderWidth 512.5\n}\n",
                 "t.scene:2:14: error: RenderWidth: expected an integer, got '512.5'"},
        BadScene{"UnquotedPath", "Mesh {\n Source a.obj\n}\n",
                 "t.scene:2:9: error: Source: expected a path in double quotes, got 'a.obj' (write \"a.obj\")"},
        BadScene{"QuotedName", "Sphere {\n Material \"m\"\n}\n",
                 "t.scene:2:11: error: Material: expected a name, got a quoted path"},
        BadScene{"NaN", "Sphere {\n Radius nan\n}\n", "t.scene:2:9: error: Radius: 'nan' is not a finite number"},
        BadScene{"Inf", "PointLight {\n Color 1 inf 1\n}\n", "t.scene:2:10: error: Color: 'inf' is not a finite number"},
        BadScene{"HugeDouble", "Camera {\n FOV 1e999\n}\n", "t.scene:2:6: error: FOV: '1e999' is not a finite number"},
        BadScene{"HugeFloat", "Sphere {\n Radius 1e39\n}\n", "t.scene:2:9: error: Radius: '1e39' is not a finite number"},
        BadScene{"MaterialDeclaredTwice", "Material {\n Name m\n}\nMaterial {\n Name m\n}\n",
                 "t.scene:5: error: material 'm' is already declared at line 2"},
        BadScene{"TextureDeclaredTwice",
                 "Texture {\n Name t\n Source \"a.png\"\n}\nTexture {\n Name t\n Source \"b.png\"\n}\n",
                 "t.scene:6: error: texture 't' is already declared at line 2"},
        BadScene{"TextureUsedBeforeDeclared",
                 "Material {\n Name m\n DiffuseTexture t\n}\nTexture {\n Name t\n Source \"a.png\"\n}\n",
                 "t.scene:3: error: texture 't' is used before it is declared (at line 6)"},
        BadScene{"MaterialUsedBeforeDeclared", "Sphere {\n Material m\n}\nMaterial {\n Name m\n}\n",
                 "t.scene:2: error: material 'm' is used before it is declared (at line 5)"},
        BadScene{"UnknownMaterial", "Material {\n Name matWhite\n}\nSphere {\n Material matWhtie\n}\n",
                 "t.scene:5: error: unknown material 'matWhtie' (did you mean 'matWhite'?)"},
        BadScene{"RenamedMaterial", "Material {\n Name a\n Name b\n}\nSphere {\n Material a\n}\n",
                 "t.scene:6: error: unknown material 'a' (did you mean 'b'?)"},
        BadScene{"UnknownTexture", "Material {\n Name m\n NormalTexture nope\n}\n",
                 "t.scene:3: error: unknown texture 'nope'"},
        BadScene{"MaterialWithoutName", "Material {\n DiffuseColor 1 1 1\n}\n",
                 "t.scene:1: error: missing required parameter 'Name' in Material"},
        BadScene{"TextureWithoutName", "Texture {\n Source \"a.png\"\n}\n",
                 "t.scene:1: error: missing required parameter 'Name' in Texture"},
        BadScene{"TextureWithoutSource", "Texture {\n Name t\n}\n",
                 "t.scene:1: error: missing required parameter 'Source' in Texture"},
        BadScene{"MeshWithoutSource", "Mesh {\n}\n", "t.scene:1: error: missing required parameter 'Source' in Mesh"},
        BadScene{"CsgWithoutSource", "CSG {\n}\n", "t.scene:1: error: missing required parameter 'Source' in CSG"},
        BadScene{"UnreadableTexture", "Texture {\n Name t\n Source \"missing.png\"\n}\n",
                 "t.scene:3: error: cannot read texture 'missing.png': No such file or directory"},
        BadScene{"UnreadableMesh", "Mesh {\n Source \"nope/m.obj\"\n}\n",
                 "t.scene:2: error: cannot read 'nope/m.obj': No such file or directory"},
        BadScene{"UnreadableCsg", "CSG {\n Source \"nope/t.csg\"\n}\n",
                 "t.scene:2: error: cannot read 'nope/t.csg': No such file or directory"},
        BadScene{"SphereRadius", "Sphere {\n Radius -1\n}\n", "t.scene:2:9: error: Radius must be positive, got -1"},
        BadScene{"CylinderRadius", "Cylinder {\n Radius 0\n}\n", "t.scene:2:9: error: Radius must be positive, got 0"},
        BadScene{"CylinderHeight", "Cylinder {\n Height 0\n}\n", "t.scene:2:9: error: Height must be positive, got 0"},
        BadScene{"AreaWidth", "AreaLight {\n Width 0\n}\n", "t.scene:2:8: error: Width must be positive, got 0"},
        BadScene{"AreaHeight", "AreaLight {\n Height -2\n}\n", "t.scene:2:9: error: Height must be positive, got -2"},
        BadScene{"Subdivision", "AreaLight {\n Subdivision 0 5\n}\n",
                 "t.scene:2:14: error: Subdivision must be positive, got 0"},
        BadScene{"ZeroDirection", "AreaLight {\n Direction 0 0 0\n}\n",
                 "t.scene:2:12: error: Direction must not be a zero-length vector"},
        BadScene{"ZeroAxis", "Cylinder {\n Axis 0 0 0\n}\n", "t.scene:2:7: error: Axis must not be a zero-length vector"},
        BadScene{"ZeroRotationAxis", "Box {\n Rotation 0 0 0 1\n}\n",
                 "t.scene:2:11: error: Rotation axis must not be a zero-length vector"},
        BadScene{"ZeroScale", "Mesh {\n Source \"m.obj\"\n Scale 1 1 0\n}\n",
                 "t.scene:3:12: error: Scale component must not be zero (a singular transform)"},
        BadScene{"RenderWidthZero", "SceneSettings {\n RenderWidth 0\n}\n",
                 "t.scene:2:14: error: RenderWidth must be between 1 and 16384, got 0"},
        BadScene{"RenderHeightTooBig", "SceneSettings {\n RenderHeight 16385\n}\n",
                 "t.scene:2:15: error: RenderHeight must be between 1 and 16384, got 16385"},
        BadScene{"NegativeReflectionQuality", "SceneSettings {\n ReflectionQuality -1\n}\n",
                 "t.scene:2:20: error: ReflectionQuality must not be negative, got -1"},
        BadScene{"NegativeReflectionSteps", "SceneSettings {\n ReflectionSteps -2\n}\n",
                 "t.scene:2:18: error: ReflectionSteps must not be negative, got -2"},
        BadScene{"NegativeIndirectQuality", "SceneSettings {\n IndirectQuality -3\n}\n",
                 "t.scene:2:18: error: IndirectQuality must not be negative, got -3"},
        BadScene{"Unterminated", "Sphere {\n Radius 1\n",
                 "t.scene:1: error: unterminated block 'Sphere' (no '}' before the end of the file)"},
        BadScene{"CameraLooksNowhere", "Camera {\n POV 1 1 1\n POI 1 1 1\n}\n",
                 "t.scene:1: error: POV and POI coincide (the view direction has zero length)"},
        BadScene{"FieldOfView", "Camera {\n FOV 180\n}\n",
                 "t.scene:2:6: error: FOV must be between 0 and 180 degrees (exclusive), got 180"},
        BadScene{"Opacity", "Material {\n Name m\n Opacity 1.5\n}\n",
                 "t.scene:3:10: error: Opacity must be between 0 and 1, got 1.5"},
        BadScene{"ScatteringAlbedo", "Material {\n Name m\n DiffuseColor 0.5 1e6 1\n ScatteringDistance 1 1 1\n}\n",
                 "t.scene:3:2: error: DiffuseColor components must be at most 1 where ScatteringDistance is not 0 (it "
                 "is the subsurface walk's albedo), got 0.5 1000000 1"}),
    [](const auto& info) { return std::string(info.param.name); });

// Every scene and CSG file in scenes/ (the seed's, copied there, and any added later) must read without
// errors, assets included (scripts/setup.sh fetches the bunny; the build generates the head).
std::vector<std::string> sceneFolderFiles() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(test::sourcePath("scenes"), ec)) {
        const std::string ext = entry.path().extension().string();
        if (ext == ".scene" || ext == ".csg") names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

class SceneReaderSeed : public ::testing::TestWithParam<std::string> {
    void SetUp() override {
        const std::string why = test::absentFetchedAsset(test::sourcePath("scenes/" + GetParam()));
        if (!why.empty()) GTEST_SKIP() << why;
    }
};

TEST_P(SceneReaderSeed, ReadsWithoutErrors) {
    const std::string path = test::sourcePath("scenes/" + GetParam());
    Diagnostics diags;
    if (path.ends_with(".csg")) {
        EXPECT_TRUE(readCsgFile(path, diags));
        EXPECT_TRUE(diags.items.empty()) << listed(diags);
        return;
    }
    readSceneFile(path, diags);
    EXPECT_FALSE(diags.hasErrors()) << listed(diags) << "(missing assets? run scripts/setup.sh)";
}

INSTANTIATE_TEST_SUITE_P(Scenes, SceneReaderSeed, ::testing::ValuesIn(sceneFolderFiles()), [](const auto& info) {
    std::string name = info.param;
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
});

TEST(SceneReaderSeedContent, AllSeedFilesArePresent) {
    const std::vector<std::string> present = sceneFolderFiles();
    for (const char* seed :
         {"scene1_area.scene", "scene1_point.scene", "scene2_bunny.scene", "scene2_bunny_point.scene",
          "scene3_csg.scene", "scene3_csg_area.scene", "scene4_reflect.scene", "scene5_bunny_reflect.scene",
          "scene6_glossy.scene", "scene7_refract.scene", "scene8_diffuse_only.scene", "scene8_normal_only.scene",
          "scene8_textured_mesh.scene", "scene8_untextured.scene", "scene9_indirect.scene",
          "scene9_indirect_point.scene", "scene10_bunny_indirect.scene", "scene10_bunny_indirect_area.scene",
          "extra1_refract_indirect.scene", "csg_example.csg"}) {
        EXPECT_NE(std::find(present.begin(), present.end(), seed), present.end()) << seed;
    }
}

TEST(SceneReaderSeedContent, Scene1AreaHasTheThesisContents) {
    Diagnostics diags;
    const Scene s = readSceneFile(test::sourcePath("scenes/scene1_area.scene"), diags);
    ASSERT_FALSE(diags.hasErrors()) << listed(diags);
    EXPECT_EQ(s.spheres.size(), 5u);
    EXPECT_EQ(s.boxes.size(), 5u);
    EXPECT_EQ(s.materials.size(), 3u);
    ASSERT_EQ(s.areaLights.size(), 1u);
    EXPECT_EQ(s.areaLights[0].subdivisionX, 10);
    EXPECT_TRUE(s.pointLights.empty());  // commented out in the file
    EXPECT_EQ(s.settings.indirectQuality, 0);
    EXPECT_FLOAT_EQ(s.settings.colorBleeding, 4);
    expectVec(s.camera.pov, 0, 5, 15);
}

TEST(SceneReaderSeedContent, Scene3ReadsItsCsgFile) {
    Diagnostics diags;
    const Scene s = readSceneFile(test::sourcePath("scenes/scene3_csg.scene"), diags);
    ASSERT_FALSE(diags.hasErrors()) << listed(diags);
    ASSERT_EQ(s.csgs.size(), 1u);
    ASSERT_TRUE(s.csgs[0].tree);
    EXPECT_EQ(s.csgs[0].tree->nodes.size(), 9u);
    EXPECT_GE(s.csgs[0].material, 0);
}

}  // namespace
}  // namespace trazo
