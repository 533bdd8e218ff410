// embree_render: a plain Embree 3 single-ray renderer of a Trazo scene of spheres, boxes and lights (host).
// The peer a user would write instead of Trazo: Lambertian shading (Kd·(N·L)·C, no falloff, SPEC §5's
// lights), one camera ray through each pixel centre, and for an area light one jittered point in each of
// its cellsU×cellsV cells per pixel (K points per cell with --samples-per-cell K), the estimator of the
// thesis's image. The scene is read by Trazo's own reader; the tracing and shading are Embree and this file.
//
// Geometry is what a fair Embree renderer would build: boxes as 12 triangles each (one triangle geometry),
// spheres as Embree's native RTC_GEOMETRY_TYPE_SPHERE_POINT (exact ray–sphere tests, no tessellation),
// and the visible area-light rectangles as two triangles each in a geometry with its own ray mask, so
// camera rays see them and shadow rays do not (SPEC §5: lights cast no shadow).
//
// Usage: embree_render SCENE [--threads N] [--seed S] [--samples-per-cell K] [--width W --height H] -o OUT.pfm
#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "image/image_writer.h"
#include "scene/scene_reader.h"

namespace {

using trazo::Vec3;

constexpr unsigned kMaskOccluder = 1, kMaskLight = 2;
constexpr int kTile = 16;

struct Options {
    std::string scene, out = "embree.pfm";
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    uint64_t seed = 1;
    int samplesPerCell = 1;
    int width = 0, height = 0;  // 0: the scene's
};

struct AreaLightGrid {
    Vec3 center, u, v;  // u, v: full edge vectors (Width·û, Height·v̂)
    Vec3 color;
    int cellsU, cellsV;
};

// What the shading needs, indexed by Embree's geomID and primID.
struct ShadingTables {
    std::vector<Vec3> boxKd;     // per box (primID / 12)
    std::vector<Vec3> sphereKd;  // per sphere (primID)
    std::vector<Vec3> lightColor;  // per area light (primID / 2)
    unsigned boxGeom = RTC_INVALID_GEOMETRY_ID, sphereGeom = RTC_INVALID_GEOMETRY_ID,
             lightGeom = RTC_INVALID_GEOMETRY_ID;
};

// SplitMix64: a per-pixel stream, so the image depends on the seed only, not on threads or tiles.
struct PixelRng {
    uint64_t state;
    float next() {
        uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return float((z ^ (z >> 31)) >> 40) * (1.0f / 16777216.0f);
    }
};

bool parseOptions(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
        const char* v = nullptr;
        if (a == "-o" && (v = value())) o.out = v;
        else if (a == "--threads" && (v = value())) o.threads = (unsigned)std::max(1, std::atoi(v));
        else if (a == "--seed" && (v = value())) o.seed = std::strtoull(v, nullptr, 10);
        else if (a == "--samples-per-cell" && (v = value())) o.samplesPerCell = std::max(1, std::atoi(v));
        else if (a == "--width" && (v = value())) o.width = std::atoi(v);
        else if (a == "--height" && (v = value())) o.height = std::atoi(v);
        else if (!a.empty() && a[0] != '-' && o.scene.empty()) o.scene = a;
        else return false;
    }
    return !o.scene.empty();
}

// SPEC §3's rectangle axes: u = normalize(a × n), a = +Y (+Z within 0.1° of ±Y), v = n × u, rolled about n.
void areaLightAxes(Vec3 normal, float roll, Vec3& u, Vec3& v) {
    const Vec3 n = trazo::normalize(normal);
    const Vec3 a = std::fabs(n.y) > std::cos(0.1f * 3.14159265f / 180.0f) ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
    const Vec3 u0 = trazo::normalize(trazo::cross(a, n)), v0 = trazo::cross(n, u0);
    u = u0 * std::cos(roll) + v0 * std::sin(roll);
    v = v0 * std::cos(roll) - u0 * std::sin(roll);
}

Vec3 kdOf(const trazo::Scene& scene, int32_t material) {
    return material == trazo::kDefaultMaterial ? trazo::Material{}.diffuseColor : scene.materials[material].diffuseColor;
}

// Appends a triangle geometry (mask, one vertex list, index triples) to the scene and returns its geomID.
unsigned attachTriangles(RTCDevice device, RTCScene scene, const std::vector<Vec3>& vertices,
                         const std::vector<unsigned>& indices, unsigned mask) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = (float*)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                               vertices.size());
    for (size_t i = 0; i < vertices.size(); ++i) vb[3 * i] = vertices[i].x, vb[3 * i + 1] = vertices[i].y, vb[3 * i + 2] = vertices[i].z;
    auto* ib = (unsigned*)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                  indices.size() / 3);
    std::copy(indices.begin(), indices.end(), ib);
    rtcSetGeometryMask(g, mask);
    rtcCommitGeometry(g);
    const unsigned id = rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    return id;
}

void buildEmbreeScene(const trazo::Scene& scene, RTCDevice device, RTCScene rtc, ShadingTables& tables,
                      std::vector<AreaLightGrid>& grids) {
    std::vector<Vec3> vertices;
    std::vector<unsigned> indices;
    // Unit-cube corners (bit 0: x, 1: y, 2: z) and its 12 triangles; winding does not matter (two-sided).
    static const unsigned kCube[36] = {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1,
                                       2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
    for (const trazo::Box& box : scene.boxes) {
        const trazo::Affine3 worldFromUnit = trazo::composeTransforms(box.transforms);
        const unsigned base = (unsigned)vertices.size();
        for (int c = 0; c < 8; ++c)
            vertices.push_back(worldFromUnit.applyToPoint(Vec3((c & 1) ? 0.5f : -0.5f, (c & 2) ? 0.5f : -0.5f, (c & 4) ? 0.5f : -0.5f)));
        for (unsigned k : kCube) indices.push_back(base + k);
        tables.boxKd.push_back(kdOf(scene, box.material));
    }
    if (!scene.boxes.empty()) tables.boxGeom = attachTriangles(device, rtc, vertices, indices, kMaskOccluder);

    if (!scene.spheres.empty()) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* vb = (float*)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float),
                                                   scene.spheres.size());
        for (size_t i = 0; i < scene.spheres.size(); ++i) {
            const trazo::Sphere& s = scene.spheres[i];
            vb[4 * i] = s.center.x, vb[4 * i + 1] = s.center.y, vb[4 * i + 2] = s.center.z, vb[4 * i + 3] = s.radius;
            tables.sphereKd.push_back(kdOf(scene, s.material));
        }
        rtcSetGeometryMask(g, kMaskOccluder);
        rtcCommitGeometry(g);
        tables.sphereGeom = rtcAttachGeometry(rtc, g);
        rtcReleaseGeometry(g);
    }

    vertices.clear(), indices.clear();
    for (const trazo::AreaLight& l : scene.areaLights) {
        Vec3 u, v;
        areaLightAxes(l.direction, l.rollAngle, u, v);
        grids.push_back({l.position, u * l.width, v * l.height, l.color, l.subdivisionX, l.subdivisionY});
        const AreaLightGrid& g = grids.back();
        const unsigned base = (unsigned)vertices.size();
        for (int c = 0; c < 4; ++c) vertices.push_back(g.center + g.u * ((c & 1) ? 0.5f : -0.5f) + g.v * ((c & 2) ? 0.5f : -0.5f));
        for (unsigned k : {0u, 1u, 3u, 0u, 3u, 2u}) indices.push_back(base + k);
        tables.lightColor.push_back(l.color);
    }
    if (!grids.empty()) tables.lightGeom = attachTriangles(device, rtc, vertices, indices, kMaskLight);
    rtcCommitScene(rtc);
}

// Everything a tile worker reads; the counters are the only shared writes.
struct RenderJob {
    const trazo::Scene* scene;
    RTCScene rtc;
    const ShadingTables* tables;
    const std::vector<AreaLightGrid>* grids;
    int width, height, samplesPerCell;
    uint64_t seed;
    Vec3 origin, forward, right, up;
    float tanHalfFovY;
    std::vector<Vec3>* image;
    std::atomic<int> nextTile{0};
    std::atomic<uint64_t> rays{0};
};

bool occludedSegment(RTCScene rtc, Vec3 from, Vec3 to) {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRay r{};
    r.org_x = from.x, r.org_y = from.y, r.org_z = from.z;
    const Vec3 d = to - from;
    r.dir_x = d.x, r.dir_y = d.y, r.dir_z = d.z;
    r.tnear = 0.0f;
    r.tfar = 1.0f - 1e-4f;  // d is unnormalised: t = 1 is the light point
    r.mask = kMaskOccluder;
    rtcOccluded1(rtc, &ctx, &r);
    return r.tfar < 0.0f;
}

// Kd·(N·L)·C when the point X is visible from P (N faces the viewer); counts the shadow ray it traces.
Vec3 lambertFrom(const RenderJob& job, Vec3 p, Vec3 n, Vec3 kd, Vec3 x, Vec3 color, uint64_t& rays) {
    const Vec3 toLight = x - p;
    const float cosine = trazo::dot(n, toLight);
    if (cosine <= 0.0f) return Vec3(0.0f);  // no light reaches this side: no shadow ray either
    ++rays;
    if (occludedSegment(job.rtc, p, x)) return Vec3(0.0f);
    return kd * color * (cosine / trazo::length(toLight));
}

Vec3 shadePixel(const RenderJob& job, int px, int py, uint64_t& rays) {
    const float sx = (2.0f * (px + 0.5f) / job.width - 1.0f) * job.tanHalfFovY * job.width / job.height;
    const float sy = (1.0f - 2.0f * (py + 0.5f) / job.height) * job.tanHalfFovY;
    const Vec3 dir = trazo::normalize(job.forward + job.right * sx + job.up * sy);
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh{};
    rh.ray.org_x = job.origin.x, rh.ray.org_y = job.origin.y, rh.ray.org_z = job.origin.z;
    rh.ray.dir_x = dir.x, rh.ray.dir_y = dir.y, rh.ray.dir_z = dir.z;
    rh.ray.tfar = INFINITY;
    rh.ray.mask = kMaskOccluder | kMaskLight;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(job.rtc, &ctx, &rh);
    ++rays;
    const ShadingTables& t = *job.tables;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return job.scene->settings.backgroundColor;
    if (rh.hit.geomID == t.lightGeom) return t.lightColor[rh.hit.primID / 2];
    const Vec3 kd = rh.hit.geomID == t.boxGeom ? t.boxKd[rh.hit.primID / 12] : t.sphereKd[rh.hit.primID];
    Vec3 n = trazo::normalize(Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
    if (trazo::dot(n, dir) > 0.0f) n = -n;  // face the viewer (SPEC §5)
    // Shadow rays start off the surface by an offset that scales with the hit point's magnitude.
    const Vec3 hit = job.origin + dir * rh.ray.tfar;
    const float scale = std::max({1.0f, std::fabs(hit.x), std::fabs(hit.y), std::fabs(hit.z)});
    const Vec3 p = hit + n * (1e-4f * scale);

    Vec3 sum(0.0f);
    for (const trazo::PointLight& l : job.scene->pointLights) sum += lambertFrom(job, p, n, kd, l.position, l.color, rays);
    PixelRng rng{job.seed * 0x100000001b3ull + (uint64_t)py * job.width + px};
    for (const AreaLightGrid& g : *job.grids) {
        Vec3 lightSum(0.0f);
        for (int j = 0; j < g.cellsV; ++j)
            for (int i = 0; i < g.cellsU; ++i)
                for (int k = 0; k < job.samplesPerCell; ++k) {
                    const float su = (i + rng.next()) / g.cellsU - 0.5f, sv = (j + rng.next()) / g.cellsV - 0.5f;
                    lightSum += lambertFrom(job, p, n, kd, g.center + g.u * su + g.v * sv, g.color, rays);
                }
        sum += lightSum / float(g.cellsU * g.cellsV * job.samplesPerCell);
    }
    return sum;
}

void renderTiles(RenderJob& job) {
    const int tilesX = (job.width + kTile - 1) / kTile, tilesY = (job.height + kTile - 1) / kTile;
    uint64_t rays = 0;
    for (int tile; (tile = job.nextTile++) < tilesX * tilesY;) {
        const int x0 = (tile % tilesX) * kTile, y0 = (tile / tilesX) * kTile;
        for (int y = y0; y < std::min(y0 + kTile, job.height); ++y)
            for (int x = x0; x < std::min(x0 + kTile, job.width); ++x)
                (*job.image)[(size_t)y * job.width + x] = shadePixel(job, x, y, rays);
    }
    job.rays += rays;
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    if (!parseOptions(argc, argv, opt)) {
        std::fprintf(stderr, "usage: embree_render SCENE [--threads N] [--seed S] [--samples-per-cell K] "
                             "[--width W --height H] [-o OUT.pfm]\n");
        return 2;
    }
    trazo::Diagnostics diags;
    const trazo::Scene scene = trazo::readSceneFile(opt.scene, diags);
    trazo::printDiagnostics(diags);
    if (diags.hasErrors()) return 2;
    if (!scene.cylinders.empty() || !scene.meshes.empty() || !scene.csgs.empty())
        std::fprintf(stderr, "embree_render: draws spheres, boxes and lights only; cylinders, meshes and CSG are skipped\n");

    using Clock = std::chrono::steady_clock;
    const auto buildStart = Clock::now();
    const std::string config = "threads=" + std::to_string(opt.threads);
    RTCDevice device = rtcNewDevice(config.c_str());
    RTCScene rtc = rtcNewScene(device);
    ShadingTables tables;
    std::vector<AreaLightGrid> grids;
    buildEmbreeScene(scene, device, rtc, tables, grids);
    const double buildSeconds = std::chrono::duration<double>(Clock::now() - buildStart).count();

    RenderJob job;
    job.scene = &scene, job.rtc = rtc, job.tables = &tables, job.grids = &grids;
    job.width = opt.width > 0 ? opt.width : scene.settings.renderWidth;
    job.height = opt.height > 0 ? opt.height : scene.settings.renderHeight;
    job.samplesPerCell = opt.samplesPerCell, job.seed = opt.seed;
    // The camera of SPEC §3 (vertical FOV, +Y up, +Z when looking straight up or down).
    job.origin = scene.camera.pov;
    job.forward = trazo::normalize(scene.camera.poi - scene.camera.pov);
    const Vec3 worldUp = std::fabs(job.forward.y) > 0.9999f ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
    job.right = trazo::normalize(trazo::cross(job.forward, worldUp));
    job.up = trazo::cross(job.right, job.forward);
    job.tanHalfFovY = std::tan(0.5f * scene.camera.fovDegrees * 3.14159265f / 180.0f);
    std::vector<Vec3> image((size_t)job.width * job.height);
    job.image = &image;

    const auto renderStart = Clock::now();
    std::vector<std::thread> workers;
    for (unsigned i = 0; i < opt.threads; ++i) workers.emplace_back(renderTiles, std::ref(job));
    for (std::thread& w : workers) w.join();
    const double renderSeconds = std::chrono::duration<double>(Clock::now() - renderStart).count();

    rtcReleaseScene(rtc);
    rtcReleaseDevice(device);
    std::string error;
    if (!trazo::writeImage(opt.out, job.width, job.height, image, error)) {
        std::fprintf(stderr, "embree_render: %s\n", error.c_str());
        return 1;
    }
    const uint64_t rays = job.rays;
    std::printf("build %.4f s, render %.4f s, %llu rays, %.2f Mrays/s, %d x %d, %u threads, %d sample(s) per cell\n",
                buildSeconds, renderSeconds, (unsigned long long)rays, rays / renderSeconds * 1e-6, job.width,
                job.height, opt.threads, opt.samplesPerCell);
    return 0;
}
