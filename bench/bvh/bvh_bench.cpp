// bvh_bench: BVH build time and quality, and Mrays/s of primary, shadow and random rays, over the bunny and
// a generated ≥1M-triangle mesh; with Embree 3, the same scenes and rays traced by Embree for comparison.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "accel/bvh_build.h"
#include "accel/collapse_bvh.h"
#include "core/rng.h"
#include "flatten/flatten_mesh.h"
#include "backends/backend.h"
#include "backends/cpu/cpu_kernels.h"
#include "scene/obj_reader.h"
#include "support/tessellate.h"
#if TRAZO_HAVE_EMBREE
#include "embree_scene.h"
#endif
#if TRAZO_BVH_BENCH_GPU_NODES
#include "gpu_node_width.h"
#endif

namespace {

using namespace trazo;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The mesh as the renderer holds it (appendMesh: BVH, wide nodes, triangles in leaf order; the mesh the one
// object of the top level), queried through the CPU backend's ray-query loop compiled for the instruction set
// the renderer picks on this CPU (selectCpuKernels; TRAZO_CPU_ISA forces one), so the figures are the
// renderer's. Queries cover (0, tMax): shadow rays start a little off the surface, as the renderer's do.
struct TriangleScene {
    std::vector<Vec3> triangles;  // original order (what Embree gets)
    SceneArrays arrays;
    EightWideMeshes meshes8;
    SceneView view;
    Aabb bounds;

    explicit TriangleScene(std::vector<Vec3> tris) : triangles(std::move(tris)) {
        PreparedMesh mesh;
        for (size_t i = 0; i + 2 < triangles.size(); i += 3) {
            mesh.triangles.push_back({triangles[i], triangles[i + 1], triangles[i + 2]});
            bounds.grow(triangleBounds(triangles[i], triangles[i + 1], triangles[i + 2]));
        }
        mesh.corners.resize(mesh.triangles.size());
        arrays.objects.push_back({ObjectKind::Mesh, appendMesh(mesh, arrays), 0});
        arrays.topNodes = collapseBvh(buildBvh({wideNodeBounds(arrays.meshNodes[0])}));
        // As the CPU backend's upload: the eight-wide nodes where its AVX2 or AVX-512 kernels run.
        if (selectCpuKernels().isa != CpuIsa::Sse2) widenMeshBvhs(arrays, meshes8);
        view = hostView(arrays);
        viewEightWide(view, meshes8);
    }
    // out[i] = the nearest t of queries[i] (+inf on a miss), or 1/0 for a shadow query.
    void answer(const RayQuery* queries, size_t count, bool shadow, float* out) const {
        RayAnswer answers[kChunk];
        const CpuKernels& kernels = selectCpuKernels();
        for (size_t done = 0; done < count; done += kChunk) {
            const size_t n = std::min(kChunk, count - done);
            kernels.answerRayQueries(view, queries + done, n, shadow ? RayQueryKind::Shadow : RayQueryKind::Nearest,
                                     answers);
            for (size_t i = 0; i < n; ++i) out[done + i] = answers[i].t;
        }
    }
    // The tree shadow rays take in this mesh (MeshShape::anyHit8), to time the other one: whether
    // kMeshAnyHit8Triangles still sits where the two trees cross on this machine.
    bool anyHit8() const { return arrays.meshes[0].anyHit8 != 0; }
    void setAnyHit8(bool on) { arrays.meshes[0].anyHit8 = on; }  // the view reads the arrays' memory
    static constexpr size_t kChunk = 256;
};

std::vector<Aabb> boundsOf(const std::vector<Vec3>& tris) {
    std::vector<Aabb> b(tris.size() / 3);
    for (size_t i = 0; i < b.size(); ++i) b[i] = triangleBounds(tris[3 * i], tris[3 * i + 1], tris[3 * i + 2]);
    return b;
}

// A ray's expected eight-wide node visits and leaf-block tests, given that it meets the root's box: Σ area over
// the root's area, counted as Embree's statistics count them (--tree-stats), so the trees compare.
struct TreeCost {
    double nodes = 0.0, blocks = 0.0;
};
TreeCost treeCost(const std::vector<WideBvhNode8>& nodes) {
    TreeCost cost;
    if (nodes.empty()) return cost;
    const double rootArea = usedLanesBounds(nodes[0]).surfaceArea();
    if (rootArea <= 0.0) return cost;
    for (const WideBvhNode8& n : nodes) {  // one mesh's tree: every node is reached once
        cost.nodes += usedLanesBounds(n).surfaceArea() / rootArea;
        for (int lane = 0; lane < kBvh8Width; ++lane)
            if (n.child[lane] != kBvhEmptyLane && bvhIsLeaf(n.child[lane]))
                cost.blocks += laneBox(n, lane).surfaceArea() / rootArea * bvhLeafCount(n.child[lane]);
    }
    return cost;
}

// Best of `runs` builds (binary SAH build, then the collapse to wide nodes), in seconds.
double timeBuild(const std::vector<Aabb>& bounds, unsigned threads, int runs) {
    double best = 1e30;
    for (int r = 0; r < runs; ++r) {
        BvhBuildOptions options = triangleBvhOptions();
        options.threads = threads;
        const auto start = Clock::now();
        const Bvh bvh = buildBvh(bounds, options);
        const std::vector<WideBvhNode> nodes = collapseBvh(bvh);
        best = std::min(best, secondsSince(start));
    }
    return best;
}

// Runs fn(begin, end) over [0, n) on `threads` threads (interleaved chunks), returns seconds.
template <class Fn>
double parallelFor(size_t n, unsigned threads, Fn&& fn) {
    const auto start = Clock::now();
    std::vector<std::thread> pool;
    constexpr size_t kChunk = 4096;
    auto work = [&](unsigned part) {
        for (size_t c = part * kChunk; c < n; c += (size_t)threads * kChunk) fn(c, std::min(n, c + kChunk));
    };
    for (unsigned p = 1; p < threads; ++p) pool.emplace_back(work, p);
    work(0);
    for (std::thread& t : pool) t.join();
    return secondsSince(start);
}

struct RaySets {
    std::vector<RayQuery> primary, shadow, random;
};

// Primary rays of a 1024² pinhole camera framing the mesh; shadow rays from their hits to a point light
// above the camera; random rays with origins in the bounds and uniform directions.
RaySets makeRays(const TriangleScene& scene) {
    RaySets sets;
    const Vec3 center = scene.bounds.centroid();
    const float radius = 0.5f * length(scene.bounds.extent());
    const Vec3 eye = center + normalize(Vec3(0.3f, 0.4f, 1.0f)) * (2.6f * radius);
    const Vec3 forward = normalize(center - eye), right = normalize(cross(forward, Vec3(0, 1, 0))),
               up = cross(right, forward);
    const float tanHalf = std::tan(0.5f * 45.0f * 3.14159265f / 180.0f);
    constexpr int kSize = 1024;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const float sx = (2.0f * (x + 0.5f) / kSize - 1.0f) * tanHalf, sy = (1.0f - 2.0f * (y + 0.5f) / kSize) * tanHalf;
            sets.primary.push_back({{eye, normalize(forward + right * sx + up * sy)}, INFINITY});
        }
    std::vector<float> hits(sets.primary.size());
    parallelFor(hits.size(), std::max(1u, std::thread::hardware_concurrency()),
                [&](size_t begin, size_t end) { scene.answer(&sets.primary[begin], end - begin, false, &hits[begin]); });
    const Vec3 light = eye + up * (1.5f * radius) + right * (0.5f * radius);
    const float epsilon = 1e-4f * radius;  // keeps shadow rays off the surface they start on
    for (size_t i = 0; i < hits.size(); ++i) {
        if (!std::isfinite(hits[i])) continue;
        const Vec3 p = pointAt(sets.primary[i].ray, hits[i]);
        const float distance = length(light - p);
        const Vec3 direction = (light - p) / distance;
        sets.shadow.push_back({{p + direction * epsilon, direction}, distance - epsilon});
    }
    for (uint32_t i = 0; i < kSize * kSize; ++i) {
        auto u = [&](uint32_t d) { return bitsToUnitFloat(hashCombine(hashU32(i), d)); };
        const Vec3 o = scene.bounds.min + scene.bounds.extent() * Vec3(u(0), u(1), u(2));
        const float z = 1.0f - 2.0f * u(3), phi = 6.2831853f * u(4), s = std::sqrt(std::max(0.0f, 1.0f - z * z));
        sets.random.push_back({{o, Vec3(s * std::cos(phi), s * std::sin(phi), z)}, INFINITY});
    }
    return sets;
}

// Command-line choices that shorten an iteration: a subset of scenes and ray kinds, every k-th ray, and
// best-of-R timing with Trazo and Embree interleaved (on a loaded machine, both see the same noise).
struct BenchOptions {
    unsigned threads = 1;
    size_t rays = 0;         // 0 = all; else about this many per kind, taken at an even stride
    const char* only = "";   // "" = all kinds, else primary, shadow or random
    const char* scene = "";  // "" = both, else bunny or sphere
    uint32_t sphereRings = 708;  // the sphere's rings and segments: 2·n·(n − 1) triangles
    int repeat = 1;
    bool build = true;       // time the builds (the 1M-triangle ones take seconds)
    bool treeStats = false;  // Embree prints its BVH's statistics (and device banner) as it builds
};

std::vector<RayQuery> subsample(const std::vector<RayQuery>& all, size_t count) {
    if (count == 0 || count >= all.size()) return all;
    std::vector<RayQuery> out;
    const double stride = (double)all.size() / (double)count;
    for (size_t k = 0; k < count; ++k) out.push_back(all[(size_t)(k * stride)]);
    return out;
}

void benchScene(const char* name, std::vector<Vec3> triangles, const BenchOptions& opt) {
    const unsigned threads = opt.threads;
    const std::vector<Aabb> bounds = boundsOf(triangles);
    const uint32_t count = (uint32_t)bounds.size();
    const int runs = count > 200000 ? 2 : 5;
    const double build1 = opt.build ? timeBuild(bounds, 1, runs) : 0.0,
                 buildN = opt.build ? timeBuild(bounds, threads, runs) : 0.0;
    const Bvh binary = buildBvh(bounds, triangleBvhOptions());  // the tree appendMesh builds, for its statistics
    TriangleScene scene(std::move(triangles));
    const std::vector<WideBvhNode>& nodes = scene.arrays.meshNodes;

    std::printf("\n== %s: %u triangles ==\n", name, count);
    std::printf("Trazo build: %.1f ms (1 thread), %.1f ms (%u threads); %zu binary nodes (SAH cost %.2f, depth %u) "
                "-> %zu wide nodes (depth %u, %.1f MB)\n",
                build1 * 1e3, buildN * 1e3, threads, binary.nodes.size(), bvhSahCost(binary, triangleBvhOptions()),
                bvhDepth(binary), nodes.size(), wideBvhDepth(nodes), nodes.size() * sizeof(WideBvhNode) * 1e-6);
    if (!scene.meshes8.nodes.empty()) {  // what the CPU backend's upload adds for its AVX2 / AVX-512 kernels
        // Made in fresh memory (the first upload), and again in the same (an edit that moved the mesh).
        SceneArrays arrays = scene.arrays;
        double fresh = 1e30, again = 1e30;
        for (int r = 0; r < runs; ++r) {
            EightWideMeshes widened;
            auto start = Clock::now();
            widenMeshBvhs(arrays, widened);
            fresh = std::min(fresh, secondsSince(start));
            start = Clock::now();
            widenMeshBvhs(arrays, widened);
            again = std::min(again, secondsSince(start));
        }
        const EightWideMeshes& m = scene.meshes8;
        std::printf("-> %zu eight-wide nodes and %zu leaf blocks for the %s kernels (%.1f + %.1f MB, made in %.1f ms; "
                    "%.1f ms in the memory of the last)\n",
                    m.nodes.size(), m.blocks.size(), cpuIsaName(selectCpuKernels().isa),
                    m.nodes.size() * sizeof(WideBvhNode8) * 1e-6, m.blocks.size() * sizeof(TriangleBlock) * 1e-6,
                    fresh * 1e3, again * 1e3);
        const TreeCost cost = treeCost(m.nodes);
        std::printf("   a ray meeting its box visits %.2f nodes and tests %.2f leaf blocks (expected: area over the "
                    "root's)\n",
                    cost.nodes, cost.blocks);
    }

    // The GPU, when there is one: the same scene and queries through the CUDA backend.
    std::string gpuStatus, error;
    std::unique_ptr<Backend> gpu;
    if (cudaDeviceAvailable(gpuStatus)) {
        gpu = createBackend(BackendChoice::Cuda, 0, error);
        if (gpu) gpu->upload(scene.arrays);
        else gpuStatus = error;
    }
    std::vector<std::string> gpuLines;
#if TRAZO_BVH_BENCH_GPU_NODES
    // The eight-wide nodes the node-format line traces: widenBvh's, whose leaves name triangles (the CPU kernels'
    // name their TriangleBlocks).
    const std::vector<WideBvhNode8> gpuNodes8 =
        gpu ? widenBvh(nodes.data(), nodes.size()) : std::vector<WideBvhNode8>{};
#endif

    const RaySets sets = makeRays(scene);
    struct Kind {
        const char* name;
        const std::vector<RayQuery>* rays;
        bool shadow;
    } kinds[] = {{"primary", &sets.primary, false}, {"shadow", &sets.shadow, true}, {"random", &sets.random, false}};

#if TRAZO_HAVE_EMBREE
    const bench::EmbreeScene embree1(scene.triangles, 1, opt.treeStats);
    const bench::EmbreeScene embreeN(scene.triangles, 0);
    std::printf("Embree build (default quality): %.1f ms (1 thread), %.1f ms (all threads)\n",
                embree1.buildSeconds() * 1e3, embreeN.buildSeconds() * 1e3);
    std::printf("%-8s %9s %8s | %12s %12s | %12s %12s | %8s %8s %10s\n", "rays", "count", "hit %", "Trazo 1T",
                "Trazo NT", "Embree 1T", "Embree NT", "ratio 1T", "ratio NT", "agreement");
#else
    std::printf("%-8s %9s %8s | %12s %12s\n", "rays", "count", "hit %", "Trazo 1T", "Trazo NT");
#endif
    for (const Kind& k : kinds) {
        if (*opt.only && std::strcmp(opt.only, k.name)) continue;
        const std::vector<RayQuery> rays = subsample(*k.rays, opt.rays);
        std::vector<float> result(rays.size());
        auto trace = [&](size_t begin, size_t end) {
            scene.answer(&rays[begin], end - begin, k.shadow, &result[begin]);
        };
        double t1 = 1e30, tN = 1e30, tOther = 1e30;
        // Shadow rays over the tree the renderer does not take for them, where the mesh has both.
        const bool otherTree = k.shadow && !scene.meshes8.nodes.empty();
        std::vector<float> otherResult(otherTree ? rays.size() : 0);
        auto traceOther = [&](size_t begin, size_t end) {
            scene.answer(&rays[begin], end - begin, true, &otherResult[begin]);
        };
#if TRAZO_HAVE_EMBREE
        double te = 1e30, teN = 1e30;
        std::vector<float> theirs(rays.size());
        auto traceEmbreeOn = [&](const bench::EmbreeScene& embree) {
            return [&, e = &embree](size_t begin, size_t end) {
                for (size_t i = begin; i < end; ++i) {
                    const RayQuery& q = rays[i];
                    theirs[i] = k.shadow ? (float)e->occluded(q.ray, 0.0f, q.tMax) : e->intersect(q.ray, 0.0f, q.tMax);
                }
            };
        };
        const auto traceEmbree = traceEmbreeOn(embree1), traceEmbreeN = traceEmbreeOn(embreeN);
#endif
        for (int r = 0; r < opt.repeat; ++r) {
            t1 = std::min(t1, parallelFor(rays.size(), 1, trace));
#if TRAZO_HAVE_EMBREE
            te = std::min(te, parallelFor(rays.size(), 1, traceEmbree));
#endif
            if (otherTree) {
                scene.setAnyHit8(!scene.anyHit8());
                tOther = std::min(tOther, parallelFor(rays.size(), 1, traceOther));
                scene.setAnyHit8(!scene.anyHit8());
            }
        }
#if TRAZO_HAVE_EMBREE
        // Against the one-thread build's answers, before the all-thread one's replace them in `theirs`.
        size_t agree = 0;
        for (size_t i = 0; i < rays.size(); ++i)
            agree += k.shadow ? (result[i] != 0.0f) == (theirs[i] != 0.0f) : std::isfinite(result[i]) == std::isfinite(theirs[i]);
#endif
        for (int r = 0; r < opt.repeat; ++r) {
            tN = std::min(tN, parallelFor(rays.size(), threads, trace));
#if TRAZO_HAVE_EMBREE
            teN = std::min(teN, parallelFor(rays.size(), threads, traceEmbreeN));
#endif
        }
        size_t hits = 0;
        for (float r : result) hits += k.shadow ? r != 0.0f : std::isfinite(r);
        const double mr1 = rays.size() / t1 * 1e-6, mrN = rays.size() / tN * 1e-6;
#if TRAZO_HAVE_EMBREE
        const double mre = rays.size() / te * 1e-6, mreN = rays.size() / teN * 1e-6;
        std::printf("%-8s %9zu %7.2f%% | %7.2f Mr/s %7.2f Mr/s | %7.2f Mr/s %7.2f Mr/s | %7.2fx %7.2fx %9.4f%%\n", k.name,
                    rays.size(), 100.0 * hits / rays.size(), mr1, mrN, mre, mreN, mr1 / mre, mrN / mreN,
                    100.0 * agree / rays.size());
#else
        std::printf("%-8s %9zu %7.2f%% | %7.2f Mr/s %7.2f Mr/s\n", k.name, rays.size(), 100.0 * hits / rays.size(), mr1, mrN);
#endif
        if (otherTree) {
            const bool eight = scene.anyHit8();
            const double taken = rays.size() / t1 * 1e-6, other = rays.size() / tOther * 1e-6;
            std::printf("  shadow rays over the %s-wide tree instead: %.2f Mr/s (%.2fx the %s-wide the renderer takes "
                        "for %u triangles, kMeshAnyHit8Triangles = %u), %s\n",
                        eight ? "four" : "eight", other, other / taken, eight ? "eight" : "four", count,
                        kMeshAnyHit8Triangles, otherResult == result ? "the same answers" : "ANSWERS DIFFER");
        }
        if (gpu) {
            // Kernel time only (ray upload and answer download excluded); agreement with the CPU's answers.
            std::vector<float> onGpu;
            double tg = 1e30;
            const RayQueryKind kind = k.shadow ? RayQueryKind::Shadow : RayQueryKind::Nearest;
            for (int r = 0; r < opt.repeat; ++r) tg = std::min(tg, traceRayDistances(*gpu, rays, kind, onGpu));
            size_t agree = 0;
            for (size_t i = 0; i < rays.size(); ++i) agree += std::isfinite(result[i]) == std::isfinite(onGpu[i]) &&
                                                              (!k.shadow || result[i] == onGpu[i]);
            gpuLines.push_back(std::string(k.name) + ": " + std::to_string(rays.size() / tg * 1e-6) + " Mr/s, " +
                               std::to_string(100.0 * agree / rays.size()) + "% agree with the CPU");
#if TRAZO_BVH_BENCH_GPU_NODES
            // The mesh alone (no top level) over each node format: would the CPU's eight-wide nodes, or quantized
            // ones, pay on the device?
            const GpuNodeWidthTiming w =
                timeGpuNodeWidths(nodes, gpuNodes8, scene.arrays.triangles, rays, k.shadow, opt.repeat);
            std::string line = "  mesh only: ";
            if (!w.ran) line += "node formats not measured: " + w.why;
            for (int f = 0; w.ran && f < kNodeFormats; ++f) {
                char part[200];
                std::snprintf(part, sizeof part,
                              "%s%s %.0f Mr/s (%.2fx, %.4f%% the same answers, %zu rays short of stack)", f ? "; " : "",
                              kNodeFormatNames[f], rays.size() / w.seconds[f] * 1e-6, w.seconds[0] / w.seconds[f],
                              100.0 * w.agree[f] / rays.size(), w.stackOverflows[f]);
                line += part;
            }
            gpuLines.push_back(line);
#endif
        }
    }
    if (gpu) {
        std::printf("GPU (%s, kernel time):\n", gpu->deviceName().c_str());
        for (const std::string& line : gpuLines) std::printf("  %s\n", line.c_str());
    } else {
        std::printf("GPU: not measured (%s)\n", gpuStatus.empty() ? "this build has no CUDA backend" : gpuStatus.c_str());
    }
}

}  // namespace

int main(int argc, char** argv) {
    BenchOptions opt;
    opt.threads = std::max(1u, std::thread::hardware_concurrency());
    for (int i = 1; i < argc; ++i) {
        const bool more = i + 1 < argc;
        if (!std::strcmp(argv[i], "--threads") && more) opt.threads = (unsigned)std::max(1, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--rays") && more) opt.rays = (size_t)std::max(0, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--only") && more) opt.only = argv[++i];
        else if (!std::strcmp(argv[i], "--scene") && more) opt.scene = argv[++i];
        else if (!std::strcmp(argv[i], "--repeat") && more) opt.repeat = std::max(1, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--sphere-rings") && more) opt.sphereRings = (uint32_t)std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--no-build")) opt.build = false;
        else if (!std::strcmp(argv[i], "--tree-stats")) opt.treeStats = true;
        else {
            std::fprintf(stderr,
                         "usage: bvh_bench [--threads N] [--rays N] [--only primary|shadow|random] [--scene bunny|sphere]\n"
                         "                 [--sphere-rings N] [--repeat R] [--no-build] [--tree-stats]\n"
                         "  --rays N     about N rays per kind (an even stride through the full set)\n"
                         "  --repeat R   best of R timings, Trazo and Embree interleaved\n"
                         "  --no-build   skip the build timings\n"
                         "  --sphere-rings N  the bumpy sphere's rings and segments, 8..2000\n"
                         "                    (708: 1,001,112 triangles)\n"
                         "  --tree-stats Embree prints its BVH's statistics as it builds, to compare with Trazo's\n"
                         "               expected node visits and leaf-block tests\n");
            return 2;
        }
    }
    if (opt.sphereRings < 8 || opt.sphereRings > 2000) {
        std::fprintf(stderr, "bvh_bench: --sphere-rings must be 8..2000, not %u\n", opt.sphereRings);
        return 2;
    }
    const unsigned threads = opt.threads;
    std::printf("bvh_bench: %u threads (1T = one thread, NT = %u threads); Trazo's CPU kernels: %s\n", threads, threads,
                cpuIsaName(selectCpuKernels().isa));
#if !TRAZO_HAVE_EMBREE
    std::printf("Embree not found: comparison skipped\n");
#endif

    const std::string bunnyPath = std::string(TRAZO_SOURCE_DIR) + "/scenes/assets/bunny.obj";
    Diagnostics diags;
    const auto mesh = readObjFile(bunnyPath, diags);
    if (*opt.scene && std::strcmp(opt.scene, "bunny")) {
        // skipped
    } else if (mesh) {
        std::vector<Vec3> tris;
        for (const auto& corner : mesh->corners) tris.push_back(mesh->positions[corner.position]);
        benchScene("bunny (scenes/assets/bunny.obj)", std::move(tris), opt);
    } else {
        std::printf("\n%s is missing or unreadable: make it with scripts/make_bunny.sh\n", bunnyPath.c_str());
    }
    // By default 2·708·707 = 1,001,112 triangles, displaced so the surface is not a plain sphere.
    if (!*opt.scene || !std::strcmp(opt.scene, "sphere")) {
        const uint32_t n = opt.sphereRings;
        const std::string name = "bumpy sphere (tessellateSphere, " + std::to_string(n) + " rings x " +
                                 std::to_string(n) + " segments)";
        benchScene(name.c_str(), tessellateSphere({0, 0, 0}, 1.0f, n, n, 0.08f), opt);
    }
    return 0;
}
