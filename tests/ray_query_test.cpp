// Scene-level ray queries: the two-level BVH (the top level over objects, one BVH per mesh) must answer as
// testing every object and every triangle does, through the CPU backend's traceRays; the CUDA backend must
// answer the same queries alike (skipped without a device).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "backends/backend.h"
#include "core/rng.h"
#include "accel/collapse_bvh.h"
#include "flatten/flatten.h"
#include "fetched_assets.h"
#include "scene/scene_reader.h"
#include "test_paths.h"

namespace trazo::test {
namespace {

SceneArrays loadArrays(const std::string& relativePath) {
    Diagnostics diags;
    const Scene scene = readSceneFile(sourcePath(relativePath), diags);
    EXPECT_FALSE(diags.hasErrors()) << relativePath;
    return flatten(scene).arrays;
}

// Nearest t in (0, tMax) over every object, meshes triangle by triangle, and (unless `objectsOnly`) every
// area-light rectangle; +inf when nothing is hit.
float bruteForceNearest(const SceneView& scene, const RayQuery& q, bool objectsOnly) {
    float best = q.tMax;
    bool found = false;
    const TriangleRay tr = makeTriangleRay(q.ray);
    for (uint32_t i = 0; i < scene.objects.count; ++i) {
        const ObjectRef& o = scene.objects[i];
        if (o.kind == ObjectKind::Mesh) {
            const MeshShape& mesh = scene.meshes[o.index];
            for (uint32_t t = mesh.triangleOffset; t < mesh.triangleOffset + mesh.triangleCount; ++t) {
                TriangleHit h;
                const MeshTriangle& tri = scene.triangles[t];
                if (intersectTriangle(tr, tri.p0, tri.p1, tri.p2, 0.0f, best, h)) best = h.t, found = true;
            }
            continue;
        }
        ShapeHit h;
        if (intersectObject(scene, o, q.ray, best, h)) best = h.t, found = true;
    }
    for (uint32_t i = 0; i < scene.areaLights.count && !objectsOnly; ++i) {
        ShapeHit h;
        if (intersectRectangle(scene.areaLights[i].rect, q.ray, 0.0f, best, h)) best = h.t, found = true;
    }
    return found ? best : INFINITY;
}

// Rays from random points of the scene's bounds in random directions, half of them aimed at an object's
// centre, and half of those cut short at a random distance (for shadow queries).
std::vector<RayQuery> sceneRays(const SceneArrays& arrays, uint32_t count, uint32_t seed) {
    Aabb bounds;
    for (const WideBvhNode& node : arrays.topNodes) bounds.grow(wideNodeBounds(node));
    std::vector<RayQuery> rays;
    for (uint32_t i = 0; i < count; ++i) {
        auto u = [&](uint32_t d) { return bitsToUnitFloat(hashCombine(hashU32(seed * 7919u + i), d)); };
        const Vec3 origin = bounds.min + bounds.extent() * Vec3(u(0), u(1), u(2));
        Vec3 direction = Vec3(u(3), u(4), u(5)) * 2.0f - Vec3(1.0f);
        if (i % 2) {
            const Aabb target = wideNodeBounds(arrays.topNodes[0]);
            direction = target.min + target.extent() * Vec3(u(6), u(7), u(8)) - origin;
        }
        rays.push_back({{origin, normalize(direction)}, i % 4 == 3 ? u(9) * length(bounds.extent()) : INFINITY});
    }
    return rays;
}

class RayQueries : public ::testing::TestWithParam<const char*> {
    void SetUp() override {
        const std::string why = absentFetchedAsset(sourcePath(std::string("scenes/") + GetParam()));
        if (!why.empty()) GTEST_SKIP() << why;
    }
};

TEST_P(RayQueries, CpuBackendMatchesBruteForce) {
    const SceneArrays arrays = loadArrays(std::string("scenes/") + GetParam());
    ASSERT_FALSE(arrays.topNodes.empty());
    const SceneView view = hostView(arrays);
    const std::vector<RayQuery> rays = sceneRays(arrays, 4000, 1);
    const std::unique_ptr<Backend> cpu = createCpuBackend(2);
    cpu->upload(arrays);
    std::vector<float> nearest, blocked;
    traceRayDistances(*cpu, rays, RayQueryKind::Nearest, nearest);
    traceRayDistances(*cpu, rays, RayQueryKind::Shadow, blocked);
    ASSERT_EQ(nearest.size(), rays.size());
    int hits = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        // The same shape and triangle tests in another order: the nearest t is the same float.
        ASSERT_EQ(nearest[i], bruteForceNearest(view, rays[i], false)) << "ray " << i;
        ASSERT_EQ(blocked[i], std::isfinite(bruteForceNearest(view, rays[i], true)) ? 1.0f : 0.0f) << "ray " << i;
        hits += std::isfinite(nearest[i]);
    }
    EXPECT_GT(hits, (int)rays.size() / 4) << "too few hits to test anything";
}

// The device runs the same traversal; only its rounding differs (FMA contraction and fast-math in the
// shape tests), which may flip a grazing ray and moves t by a few ulps.
TEST_P(RayQueries, CudaBackendMatchesCpu) {
    std::string device, error;
    if (!cudaDeviceAvailable(device)) GTEST_SKIP() << "no CUDA device (" << device << "): ray queries not compared";
    const SceneArrays arrays = loadArrays(std::string("scenes/") + GetParam());
    const std::vector<RayQuery> rays = sceneRays(arrays, 100000, 2);
    const std::unique_ptr<Backend> cpu = createCpuBackend(0);
    const std::unique_ptr<Backend> gpu = createBackend(BackendChoice::Cuda, 0, error);
    ASSERT_TRUE(gpu) << error;
    cpu->upload(arrays);
    gpu->upload(arrays);
    for (const bool shadow : {false, true}) {
        std::vector<float> onCpu, onGpu;
        const RayQueryKind kind = shadow ? RayQueryKind::Shadow : RayQueryKind::Nearest;
        traceRayDistances(*cpu, rays, kind, onCpu);
        traceRayDistances(*gpu, rays, kind, onGpu);
        ASSERT_EQ(onCpu.size(), onGpu.size());
        size_t flipped = 0, far = 0;
        for (size_t i = 0; i < rays.size(); ++i) {
            if (std::isfinite(onCpu[i]) != std::isfinite(onGpu[i]) || (shadow && onCpu[i] != onGpu[i])) {
                ++flipped;
                continue;
            }
            if (!shadow && std::isfinite(onCpu[i]) && std::fabs(onCpu[i] - onGpu[i]) > 1e-4f * std::fmax(1.0f, onCpu[i]))
                ++far;
        }
        EXPECT_LE(flipped, rays.size() / 2000) << (shadow ? "shadow" : "nearest") << " queries: hit/miss differs";
        EXPECT_LE(far, rays.size() / 2000) << "nearest queries: t differs by more than 1e-4 (relative)";
    }
}

// The stack both BVH levels share needs the top level's entries plus the neediest mesh's; every shipped scene
// must fit the CUDA kernels' fixed stack (the upload refuses a scene that does not).
TEST_P(RayQueries, TraversalStackNeedFitsTheDevice) {
    const SceneArrays arrays = loadArrays(std::string("scenes/") + GetParam());
    uint32_t meshNeed = 0;
    for (size_t i = 0; i < arrays.meshes.size(); ++i) {
        const size_t end = i + 1 < arrays.meshes.size() ? arrays.meshes[i + 1].nodeOffset : arrays.meshNodes.size();
        const uint32_t first = arrays.meshes[i].nodeOffset;
        meshNeed = std::max(meshNeed, wideBvhStackNeed(arrays.meshNodes.data() + first, end - first));
    }
    const uint32_t topNeed = wideBvhStackNeed(arrays.topNodes.data(), arrays.topNodes.size());
    EXPECT_GT(topNeed, 0u);
    EXPECT_EQ(arrays.traversalStackNeed, topNeed + meshNeed);
    EXPECT_LE(arrays.traversalStackNeed, (uint32_t)kDeviceTraversalStackSize);
    std::string why;
    EXPECT_TRUE(createCpuBackend(1)->accepts(arrays, why)) << why;
}

INSTANTIATE_TEST_SUITE_P(SeedScenes, RayQueries,
                         ::testing::Values("scene1_area.scene", "scene2_bunny.scene", "scene3_csg_area.scene",
                                           "scene8_textured_mesh.scene", "scene7_refract.scene"));

}  // namespace
}  // namespace trazo::test
