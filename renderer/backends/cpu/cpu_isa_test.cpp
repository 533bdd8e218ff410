// Tests (host) of the CPU backend's per-ISA kernels: every shipped scene renders bit for bit alike on every
// path this CPU runs (TRAZO_CPU_ISA forces one), and the environment variable chooses as documented.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

#include "accel/bvh_build.h"
#include "accel/collapse_bvh.h"
#include "backends/cpu/cpu_kernels.h"
#include "fetched_assets.h"
#include "flatten/flatten_mesh.h"
#include "integrator/packets/packet_lanes.h"
#include "integrator/scene_intersect.h"
#include "render_harness.h"
#include "support/counter_uniform.h"
#include "support/tessellate.h"
#include "test_paths.h"

namespace trazo {
namespace {

// Sets TRAZO_CPU_ISA for the scope, and restores what was there.
class ForcedIsa {
public:
    explicit ForcedIsa(const char* value) {
        if (const char* old = std::getenv("TRAZO_CPU_ISA")) old_ = old, hadOld_ = true;
        if (value) setenv("TRAZO_CPU_ISA", value, 1);
        else unsetenv("TRAZO_CPU_ISA");
    }
    ~ForcedIsa() {
        if (hadOld_) setenv("TRAZO_CPU_ISA", old_.c_str(), 1);
        else unsetenv("TRAZO_CPU_ISA");
    }

private:
    std::string old_;
    bool hadOld_ = false;
};

std::vector<CpuIsa> supportedIsas() {
    std::vector<CpuIsa> isas;
    for (CpuIsa isa : kCpuIsas) {
        if (cpuKernelsFor(isa)) isas.push_back(isa);
        else std::printf("cpu_isa: %s skipped: this CPU (or build) lacks it\n", cpuIsaName(isa));
    }
    return isas;
}

TEST(CpuIsa, EnvironmentChoosesThePath) {
    for (CpuIsa isa : supportedIsas()) {
        const ForcedIsa forced(cpuIsaName(isa));
        EXPECT_EQ(selectCpuKernels().isa, isa);
        EXPECT_EQ(cpuKernelsFor(isa)->isa, isa);
    }
    CpuIsa widest = CpuIsa::Sse2;
    for (CpuIsa isa : supportedIsas()) widest = isa;
    const ForcedIsa none(nullptr);
    EXPECT_EQ(selectCpuKernels().isa, widest);
    const ForcedIsa unknown("mmx");
    EXPECT_EQ(selectCpuKernels().isa, widest);  // with a warning
}

// All shipped scenes, small, two passes with the whole strata grids (every area-light cell at each point: the
// packets' largest blocks), on each path against the baseline.
TEST(CpuIsa, EveryPathRendersEveryShippedSceneAlike) {
    const std::vector<CpuIsa> isas = supportedIsas();
    if (isas.size() < 2) GTEST_SKIP() << "this CPU runs only the baseline path";
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::sourcePath("scenes"))) {
        if (entry.path().extension() != ".scene") continue;
        const std::string path = entry.path().string();
        if (!test::absentFetchedAsset(path).empty()) {
            std::printf("cpu_isa: %s skipped: %s\n", path.c_str(), test::absentFetchedAsset(path).c_str());
            continue;
        }
        ++scenes;
        test::RenderRequest request;
        request.passes = 2;
        request.seed = 7;
        request.width = 40;
        request.height = 30;
        request.blocks = StrataBlocks::whole();
        test::RenderedImage reference;
        {
            const ForcedIsa forced("sse2");
            reference = test::renderSceneFile(path, request);
        }
        ASSERT_EQ(reference.pixels.size(), 40u * 30u) << path;
        for (CpuIsa isa : isas) {
            if (isa == CpuIsa::Sse2) continue;
            const ForcedIsa forced(cpuIsaName(isa));
            const test::RenderedImage image = test::renderSceneFile(path, request);
            ASSERT_EQ(image.pixels.size(), reference.pixels.size());
            EXPECT_EQ(image.rays, reference.rays) << path << " on " << cpuIsaName(isa);
            EXPECT_EQ(std::memcmp(image.pixels.data(), reference.pixels.data(), image.pixels.size() * sizeof(Vec3)), 0)
                << path << " differs on " << cpuIsaName(isa);
        }
    }
    EXPECT_GT(scenes, 10);
}

// A bumpy sphere, and a flat grid of 32² quads beside it whose rays through shared vertices and edges hit several
// triangles at one t: each as its triangles' vertices, three by three.
std::vector<Vec3> bumpySphere() { return tessellateSphere({0, 0, 0}, 1.0f, 60, 70, 0.08f); }

std::vector<Vec3> quadGrid() {
    std::vector<Vec3> grid;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            const Vec3 a(3.0f + 0.125f * x, -2.0f + 0.125f * y, 0.0f), b = a + Vec3(0.125f, 0, 0),
                       c = a + Vec3(0, 0.125f, 0), d = a + Vec3(0.125f, 0.125f, 0);
            for (const Vec3& v : {a, b, d, a, d, c}) grid.push_back(v);
        }
    return grid;
}

// A direction from `origin` through one of quadGrid's vertices or edge midpoints, where triangles tie.
Vec3 towardsGridPoint(CounterUniform& u, Vec3 origin) {
    const float x = 3.0f + 0.0625f * std::floor(u(0.0f, 65.0f));
    const float y = -2.0f + 0.0625f * std::floor(u(0.0f, 65.0f));
    return normalize(Vec3(x, y, 0.0f) - origin);
}

// Meshes of those triangles, their BVHs, and a top level over them.
SceneArrays meshScene(const std::vector<std::vector<Vec3>>& meshes) {
    SceneArrays arrays;
    for (const std::vector<Vec3>& p : meshes) {
        PreparedMesh mesh;
        for (size_t i = 0; i + 2 < p.size(); i += 3) mesh.triangles.push_back({p[i], p[i + 1], p[i + 2]});
        mesh.corners.resize(mesh.triangles.size());
        arrays.objects.push_back({ObjectKind::Mesh, appendMesh(mesh, arrays), 0});
    }
    std::vector<Aabb> bounds;
    for (uint32_t i = 0; i < arrays.meshes.size(); ++i)
        bounds.push_back(wideNodeBounds(arrays.meshNodes[arrays.meshes[i].nodeOffset]));
    arrays.topNodes = collapseBvh(buildBvh(bounds));
    return arrays;
}

SceneArrays twoMeshes() { return meshScene({bumpySphere(), quadGrid()}); }

// The nearest triangle by brute force, of equal t the first in the array: what intersectMesh promises.
bool bruteForceNearest(const SceneArrays& arrays, const Ray& ray, SurfaceHit& out) {
    const TriangleRay tr = makeTriangleRay(ray);
    float tMax = INFINITY;
    bool found = false;
    for (uint32_t m = 0; m < arrays.meshes.size(); ++m) {
        const MeshShape& mesh = arrays.meshes[m];
        for (uint32_t i = mesh.triangleOffset; i < mesh.triangleOffset + mesh.triangleCount; ++i) {
            const MeshTriangle& t = arrays.triangles[i];
            TriangleHit h;
            if (!intersectTriangle(tr, t.p0, t.p1, t.p2, 0.0f, tMax, h)) continue;
            tMax = h.t;
            out.t = h.t, out.object = m, out.triangle = i, out.b1 = h.b1, out.b2 = h.b2;
            found = true;
        }
    }
    return found;
}

// Whether another triangle of the hit's mesh meets the ray at exactly the hit's t.
bool tiesWithAnother(const SceneArrays& arrays, const Ray& ray, const SurfaceHit& hit) {
    const MeshShape& mesh = arrays.meshes[hit.object];
    const TriangleRay tr = makeTriangleRay(ray);
    for (uint32_t k = mesh.triangleOffset; k < mesh.triangleOffset + mesh.triangleCount; ++k) {
        TriangleHit h;
        const MeshTriangle& t = arrays.triangles[k];
        if (k != hit.triangle && intersectTriangle(tr, t.p0, t.p1, t.p2, 0.0f, INFINITY, h) && h.t == hit.t) return true;
    }
    return false;
}

// The four-wide trees of some meshes and eight-wide ones made of them with leaves in runs of up to 1, 2 and 4
// (widenMeshBvhs' groupLeaves), each as a view with its name. The views point into the arrays: not copied.
struct MeshTrees {
    static constexpr uint32_t kGroups[] = {1, 2, 4};
    static constexpr int kCount = 1 + std::size(kGroups);
    SceneArrays widened[std::size(kGroups)];  // each tree's own nodeOffset8
    EightWideMeshes meshes8[std::size(kGroups)];
    SceneView views[kCount];
    std::string names[kCount];

    MeshTrees() = default;
    MeshTrees(const MeshTrees&) = delete;
};

// Blocks in runs of more than one where runs are asked for, and runs of three or four (one sixteen-lane test
// where AVX-512 runs) where up to four are.
void expectRunsAsAsked(const EightWideMeshes& meshes8, uint32_t group) {
    size_t runBlocks = 0, longRuns = 0;
    for (const WideBvhNode8& node : meshes8.nodes)
        for (uint32_t ref : node.child)
            if (ref != kBvhEmptyLane && bvhIsLeaf(ref) && bvhLeafCount(ref) > 1) {
                runBlocks += bvhLeafCount(ref);
                longRuns += bvhLeafCount(ref) > 2;
            }
    if (group == 1) EXPECT_EQ(runBlocks, 0u);
    else EXPECT_GT(runBlocks, meshes8.blocks.size() / 10) << "runs of " << group;
    if (group == 4) {
        EXPECT_GT(longRuns, 20u);
    }
}

void widenTrees(const SceneArrays& arrays, MeshTrees& trees) {
    static_assert(kMeshLeafGroup == 4, "the renderer's runs are among those tested");
    trees.views[0] = hostView(arrays);
    trees.names[0] = " four-wide";
    for (size_t k = 0; k < std::size(MeshTrees::kGroups); ++k) {
        const uint32_t group = MeshTrees::kGroups[k];
        trees.widened[k] = arrays;
        const bool anyHit8 = group > 1;
        widenMeshBvhs(trees.widened[k], trees.meshes8[k], group, anyHit8 ? 0 : UINT32_MAX);
        ASSERT_FALSE(trees.meshes8[k].nodes.empty());
        for (const MeshShape& mesh : trees.widened[k].meshes) ASSERT_EQ(mesh.anyHit8, anyHit8 ? 1u : 0u);
        trees.views[k + 1] = hostView(trees.widened[k]);
        viewEightWide(trees.views[k + 1], trees.meshes8[k]);
        trees.names[k + 1] = " eight-wide, runs of up to " + std::to_string(group) + " leaves" +
                             (anyHit8 ? ", shadow rays eight-wide too" : "");
        expectRunsAsAsked(trees.meshes8[k], group);
    }
}

// A packet of rays from one origin with brute force's answers, and the same rays as shadow segments that end a
// random way before or after the nearest hit.
struct RayBatch {
    Vec3 origin;
    RayPacket packet, shadows;
    SurfaceHit expected[kPacketRays];
    bool found[kPacketRays];
    bool blocked(int i) const { return found[i] && expected[i].t < shadows.tMax[i]; }
};

// Random directions, or (towardGrid) directions through the grid's vertices and edge midpoints.
RayBatch rayBatch(const SceneArrays& arrays, CounterUniform& u, Vec3 origin, bool towardGrid, size_t& hits,
                  size_t& ties) {
    RayBatch b;
    b.origin = origin;
    for (int i = 0; i < kPacketRays; ++i) {
        const Vec3 d = towardGrid ? towardsGridPoint(u, origin) : u.direction();
        b.packet.dx[i] = d.x, b.packet.dy[i] = d.y, b.packet.dz[i] = d.z, b.packet.tMax[i] = INFINITY;
    }
    b.shadows = b.packet;
    for (int i = 0; i < kPacketRays; ++i) {
        const Ray ray{origin, Vec3(b.packet.dx[i], b.packet.dy[i], b.packet.dz[i])};
        b.found[i] = bruteForceNearest(arrays, ray, b.expected[i]);
        b.shadows.tMax[i] = b.found[i] ? b.expected[i].t * u(0.5f, 1.5f) : 20.0f;
        if (!b.found[i]) continue;
        ++hits;
        ties += tiesWithAnother(arrays, ray, b.expected[i]);
    }
    return b;
}

// The camera-packet kernel's nearest hits: the same t, triangle and barycentrics, bit for bit.
void expectNearestAsBruteForce(const CameraPacketKernels& kernels, const SceneView& view, const RayBatch& b,
                               const std::string& what) {
    RayPacket rays = b.packet;
    TracedRay out[kPacketRays];
    kernels.tracePacket(view, b.origin, rays, ~0ull, out);
    for (int i = 0; i < kPacketRays; ++i) {
        const std::string where = what + ", ray " + std::to_string(i);
        ASSERT_EQ(out[i].found, b.found[i]) << where;
        if (!b.found[i]) continue;
        EXPECT_EQ(out[i].hit.t, b.expected[i].t) << where;
        EXPECT_EQ(out[i].hit.object, b.expected[i].object) << where;
        ASSERT_EQ(out[i].hit.triangle, b.expected[i].triangle) << where;
        EXPECT_EQ(out[i].hit.b1, b.expected[i].b1) << where;
        EXPECT_EQ(out[i].hit.b2, b.expected[i].b2) << where;
    }
}

// The shadow packet (where the ISA has one) and the shadow ray queries block as brute force says.
void expectShadowsAsBruteForce(const CpuKernels& kernels, const SceneView& view, const RayBatch& b,
                               const std::string& what) {
    const uint64_t blocked = kernels.occludedPacket ? kernels.occludedPacket(view, b.origin, b.shadows, ~0ull) : 0;
    RayQuery queries[kPacketRays];
    RayAnswer answers[kPacketRays];
    for (int i = 0; i < kPacketRays; ++i)
        queries[i] = RayQuery{Ray{b.origin, Vec3(b.packet.dx[i], b.packet.dy[i], b.packet.dz[i])}, b.shadows.tMax[i]};
    kernels.answerRayQueries(view, queries, kPacketRays, RayQueryKind::Shadow, answers);
    for (int i = 0; i < kPacketRays; ++i) {
        if (kernels.occludedPacket) {
            EXPECT_EQ(((blocked >> i) & 1) != 0, b.blocked(i)) << what << ", shadow packet lane " << i;
        }
        EXPECT_EQ(answers[i].t != 0.0f, b.blocked(i)) << what << ", shadow query " << i;
    }
}

// Meshes over eight-wide nodes (the AVX2 and AVX-512 kernels, SceneView::meshNodes8) answer every nearest-hit
// query as the four-wide ones and as brute force do, ties included: the same t, triangle and barycentrics,
// bit for bit, with leaves tested one at a time or in runs (widenMeshBvhs' groupLeaves); shadow queries answer
// as brute force over the four-wide trees and, where leaves run, over the eight-wide ones (anyHit8). Rays:
// random directions, and rays through the grid's vertices and edge midpoints.
TEST(CpuIsa, EightWideMeshesAnswerAsFourWideAndBruteForce) {
    const SceneArrays arrays = twoMeshes();
    MeshTrees trees;
    widenTrees(arrays, trees);
    if (HasFatalFailure()) return;

    CounterUniform u(3);
    const Vec3 origins[] = {{0.3f, 0.2f, 4.0f}, {4.5f, 0.1f, 2.0f}, {-3.0f, 0.5f, -0.5f}, {5.0f, -1.0f, -3.0f}};
    size_t hits = 0, ties = 0, rays = 0, shadowRays = 0, blockedRays = 0;
    for (const Vec3& origin : origins) {
        for (int batch = 0; batch < 40; ++batch) {
            const RayBatch b = rayBatch(arrays, u, origin, batch % 2 != 0, hits, ties);
            for (CpuIsa isa : supportedIsas()) {
                const CameraPacketKernels& cameraPackets = cpuKernelsFor(isa)->cameraPackets();
                if (!cameraPackets.available) continue;
                for (int tree = 0; tree < MeshTrees::kCount; ++tree) {
                    const std::string what = cpuIsaName(isa) + trees.names[tree] + ", batch " + std::to_string(batch);
                    expectNearestAsBruteForce(cameraPackets, trees.views[tree], b, what);
                    if (HasFatalFailure()) return;
                    expectShadowsAsBruteForce(*cpuKernelsFor(isa), trees.views[tree], b, what);
                    for (int i = 0; i < kPacketRays; ++i) shadowRays += 1, blockedRays += b.blocked(i);
                }
            }
            rays += kPacketRays;
        }
    }
    std::printf("cpu_isa: %zu rays, %zu hits, %zu of them tied with another triangle; %zu shadow queries, %zu blocked\n",
                rays, hits, ties, shadowRays, blockedRays);
    EXPECT_GT(hits, rays / 3);
    EXPECT_GT(blockedRays, shadowRays / 6);
    EXPECT_GT(ties, 100u);  // the tie-break is exercised
}

// A scene that is one mesh is queried straight through the mesh (loneMeshObject) on every path, over its four- and
// its eight-wide tree: nearest hits (ties included) and shadow segments answer as brute force does.
TEST(CpuIsa, LoneMeshAnswersAsBruteForce) {
    std::vector<Vec3> both = bumpySphere();
    const std::vector<Vec3> grid = quadGrid();
    both.insert(both.end(), grid.begin(), grid.end());
    const SceneArrays arrays = meshScene({both});
    SceneArrays widened = arrays;
    EightWideMeshes meshes8;
    widenMeshBvhs(widened, meshes8, kMeshLeafGroup, 0);
    SceneView views[2] = {hostView(arrays), hostView(widened)};
    viewEightWide(views[1], meshes8);
    ASSERT_EQ(loneMeshObject(views[0]), 0u);
    const SceneArrays two = twoMeshes();
    ASSERT_EQ(loneMeshObject(hostView(two)), kNoObject);

    CounterUniform u(9);
    const Vec3 origins[] = {{0.3f, 0.2f, 4.0f}, {4.5f, 0.1f, 2.0f}, {-3.0f, 0.5f, -0.5f}};
    constexpr int kRays = 512;
    size_t hits = 0, blocked = 0;
    for (const Vec3& origin : origins) {
        RayQuery nearest[kRays], shadow[kRays];
        SurfaceHit expected[kRays];
        bool found[kRays];
        for (int i = 0; i < kRays; ++i) {
            const Vec3 d = i % 2 ? towardsGridPoint(u, origin) : u.direction();
            nearest[i] = RayQuery{Ray{origin, d}, INFINITY};
            found[i] = bruteForceNearest(arrays, nearest[i].ray, expected[i]);
            shadow[i] = RayQuery{nearest[i].ray, found[i] ? expected[i].t * u(0.5f, 1.5f) : 20.0f};
            hits += found[i];
            blocked += found[i] && expected[i].t < shadow[i].tMax;
        }
        for (CpuIsa isa : supportedIsas()) {
            for (int tree = 0; tree < 2; ++tree) {
                RayAnswer answers[kRays], shadowAnswers[kRays];
                cpuKernelsFor(isa)->answerRayQueries(views[tree], nearest, kRays, RayQueryKind::Object, answers);
                cpuKernelsFor(isa)->answerRayQueries(views[tree], shadow, kRays, RayQueryKind::Shadow, shadowAnswers);
                for (int i = 0; i < kRays; ++i) {
                    const std::string where = std::string(cpuIsaName(isa)) + (tree ? " eight" : " four") +
                                              "-wide, ray " + std::to_string(i);
                    EXPECT_EQ(answers[i].t, found[i] ? expected[i].t : INFINITY) << where;
                    EXPECT_EQ(answers[i].object, found[i] ? 0 : kMissAnswer) << where;
                    EXPECT_EQ(shadowAnswers[i].t != 0.0f, found[i] && expected[i].t < shadow[i].tMax) << where;
                }
            }
        }
    }
    EXPECT_GT(hits, std::size(origins) * kRays / 3);
    EXPECT_GT(blocked, hits / 4);
}

}  // namespace
}  // namespace trazo
