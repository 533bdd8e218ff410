// Meshes and the top-level BVH through the whole pipeline: a finely tessellated sphere with its true
// normals renders like the analytic sphere, and the BVH's nearest hit over a crowded scene equals a brute
// force loop over every object.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "flatten/flatten.h"
#include "integrator/scene_intersect.h"
#include "render_harness.h"
#include "scene/scene_reader.h"
#include "support/tessellate.h"
#include "test_paths.h"

namespace trazo::test {
namespace {

// The tessellated sphere as an OBJ with exact per-vertex normals (the direction from the centre).
std::string writeSphereObj(uint32_t rings, uint32_t segments) {
    const std::vector<Vec3> tris = tessellateSphere(Vec3(0), 1.0f, rings, segments);
    std::ostringstream obj;
    obj.precision(9);
    for (const Vec3& p : tris) obj << "v " << p.x << ' ' << p.y << ' ' << p.z << "\n";
    for (const Vec3& p : tris) {
        const Vec3 n = normalize(p);
        obj << "vn " << n.x << ' ' << n.y << ' ' << n.z << "\n";
    }
    for (size_t t = 0; t < tris.size() / 3; ++t)
        obj << "f " << 3 * t + 1 << "//" << 3 * t + 1 << ' ' << 3 * t + 2 << "//" << 3 * t + 2 << ' ' << 3 * t + 3
            << "//" << 3 * t + 3 << "\n";
    const std::string path = tempPath("sphere.obj");
    std::ofstream(path) << obj.str();
    return path;
}

std::string sphereScene(const std::string& object) {
    return "SceneSettings\n{\nRenderWidth 64\nRenderHeight 64\nReflectionQuality 0\nIndirectQuality 0\n}\n"
           "Camera\n{\nPOV 0 0 5\nPOI 0 0 0\nFOV 30\n}\n"
           "Material\n{\nName m\nDiffuseColor 0.8 0.6 0.4\nSpecularColor 0.3 0.3 0.3\nRoughness 0.3\n}\n" + object +
           "PointLight\n{\nPosition 3 4 5\nColor 1 1 1\n}\n";
}

TEST(MeshRender, TessellatedSphereLooksLikeTheAnalyticSphere) {
    const std::string obj = writeSphereObj(128, 256);
    const RenderedImage analytic = renderSceneText(sphereScene("Sphere\n{\nMaterial m\nCenter 0 0 0\nRadius 1\n}\n"), {});
    const RenderedImage mesh =
        renderSceneText(sphereScene("Mesh\n{\nMaterial m\nSource \"" + obj + "\"\n}\n"), {});
    ASSERT_EQ(analytic.pixels.size(), mesh.pixels.size());
    ASSERT_FALSE(mesh.pixels.empty());
    // Interior pixels shade alike (interpolated normals are exact at the vertices); only silhouette pixels,
    // where the polygon's edge cuts the circle, may differ more.
    int differing = 0;
    for (size_t i = 0; i < mesh.pixels.size(); ++i) {
        const Vec3 d = abs(mesh.pixels[i] - analytic.pixels[i]);
        if (maxComponent(d) > 0.01f) ++differing;
    }
    EXPECT_LT(differing, 40) << "of " << mesh.pixels.size();  // the silhouette is ~170 pixels around
    EXPECT_LT(rmse(mesh, analytic), 0.01);
}

// intersectScene and occluded over the scene against a loop over every object, for rays from origins in
// [-15, 15]³; returns how many found something.
int checkAgainstBruteForce(const SceneView& view, std::mt19937& gen, int rays) {
    std::uniform_real_distribution<float> U(-10.0f, 10.0f);
    int hits = 0;
    for (int i = 0; i < rays; ++i) {
        const Vec3 origin(U(gen) * 1.5f, U(gen) * 1.5f, U(gen) * 1.5f);
        const Ray ray{origin, normalize(Vec3(U(gen), U(gen), U(gen)))};
        float tBest = INFINITY;
        uint32_t objectBest = kNoObject;
        ShapeHit best{};
        for (uint32_t o = 0; o < view.objects.count; ++o) {
            ShapeHit h;
            if (intersectObject(view, view.objects[o], ray, tBest, h)) {
                tBest = h.t;
                objectBest = o;
                best = h;
            }
        }
        SurfaceHit hit;
        const bool found = intersectScene(view, ray, INFINITY, hit);
        EXPECT_EQ(found, objectBest != kNoObject) << "ray " << i;
        if (!found || objectBest == kNoObject) continue;
        ++hits;
        EXPECT_EQ(hit.t, tBest) << "ray " << i;
        EXPECT_EQ(hit.object, objectBest) << "ray " << i;
        EXPECT_TRUE(hit.normal.x == best.normal.x && hit.normal.y == best.normal.y && hit.normal.z == best.normal.z)
            << "ray " << i;
        if (view.objects[objectBest].kind == ObjectKind::Mesh) {
            EXPECT_EQ(hit.triangle, best.triangle) << "ray " << i;
            EXPECT_EQ(hit.b1, best.b1) << "ray " << i;
            EXPECT_EQ(hit.b2, best.b2) << "ray " << i;
        }
        EXPECT_EQ(occluded(view, ray, tBest * 1.0001f), true);
        EXPECT_EQ(occluded(view, ray, tBest * 0.9999f), false) << "ray " << i;
    }
    return hits;
}

// 300 random spheres, boxes and cylinders: intersectScene (top-level BVH) against every object in turn.
TEST(SceneBvh, NearestHitEqualsBruteForce) {
    std::mt19937 gen(11);
    std::uniform_real_distribution<float> U(-10.0f, 10.0f), S(0.1f, 1.5f);
    std::ostringstream text;
    text << "Camera\n{\nPOV 0 0 30\nPOI 0 0 0\n}\n";
    for (int i = 0; i < 100; ++i) {
        text << "Sphere\n{\nCenter " << U(gen) << ' ' << U(gen) << ' ' << U(gen) << "\nRadius " << S(gen) << "\n}\n";
        text << "Box\n{\nTranslation " << U(gen) << ' ' << U(gen) << ' ' << U(gen) << "\nRotation " << U(gen) << ' '
             << U(gen) << ' ' << U(gen) << ' ' << U(gen) << "\nScale " << S(gen) << ' ' << S(gen) << ' ' << S(gen) << "\n}\n";
        text << "Cylinder\n{\nBase " << U(gen) << ' ' << U(gen) << ' ' << U(gen) << "\nAxis " << U(gen) << ' '
             << U(gen) << ' ' << U(gen) << "\nHeight " << S(gen) << "\nRadius " << S(gen) << "\n}\n";
    }
    Diagnostics diags;
    const Scene scene = readSceneText(text.str(), tempPath("bvh.scene"), diags);
    ASSERT_FALSE(diags.hasErrors());
    const FlattenResult flat = flatten(scene);
    const SceneView view = hostView(flat.arrays);
    ASSERT_EQ(view.objects.count, 300u);
    ASSERT_EQ(loneLeaf(view.topNodes.data), kBvhEmptyLane);
    EXPECT_GT(checkAgainstBruteForce(view, gen, 20000), 4000);  // about a quarter of the rays find something
}

// A top level that is one leaf is not traversed (loneLeaf): its objects answer alone, rays that miss their
// box included; a mesh alone in it answers its queries straight away (loneMeshObject).
TEST(SceneBvh, OneLeafTopLevelEqualsBruteForce) {
    const std::string obj = writeSphereObj(8, 16);
    const std::vector<std::string> scenes = {
        "Box\n{\nScale 12 10 8\nRotation 1 2 3 40\nTranslation 1 2 3\n}\n",
        "Mesh\n{\nSource \"" + obj + "\"\nScale 8 8 8\n}\n",
        "Sphere\n{\nCenter 0 0 0\nRadius 7\n}\nSphere\n{\nCenter 0.5 0 0\nRadius 7\n}\n"};
    for (const std::string& objects : scenes) {
        Diagnostics diags;
        const Scene scene = readSceneText("Camera\n{\nPOV 0 0 30\nPOI 0 0 0\n}\n" + objects, tempPath("lone.scene"), diags);
        ASSERT_FALSE(diags.hasErrors()) << objects;
        const FlattenResult flat = flatten(scene);
        const SceneView view = hostView(flat.arrays);
        ASSERT_NE(loneLeaf(view.topNodes.data), kBvhEmptyLane) << objects;
        EXPECT_EQ(loneMeshObject(view) != kNoObject, objects.rfind("Mesh", 0) == 0) << objects;
        std::mt19937 gen(5);
        const int hits = checkAgainstBruteForce(view, gen, 4000);
        EXPECT_GT(hits, 200) << objects;
        EXPECT_LT(hits, 3800) << objects;  // and many miss
    }
}

}  // namespace
}  // namespace trazo
