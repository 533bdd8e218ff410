// embree_render: a plain Embree 3 renderer of a Trazo scene of spheres, boxes and lights (host), in two forms.
// The peer a user would write instead of Trazo: Lambertian shading (Kd·(N·L)·C, no falloff, SPEC §5's
// lights), one camera ray through each pixel centre, and for an area light one jittered point in each of
// its cellsU×cellsV cells per pixel (K points per cell with --samples-per-cell K), the estimator of the
// thesis's image. The scene is read by Trazo's own reader; the tracing and shading are Embree and these files.
//   --mode single (default): rtcIntersect1 / rtcOccluded1, one ray at a time (embree_single.cpp);
//   --mode stream: camera rays in rtcIntersect16 packets over 8×8 tiles and each tile's shadow rays in one
//     rtcOccluded1M stream (embree_stream.cpp); --packet 1|4|8|16 (1: rtcIntersect1), --shadow-stream 1m|np and
//     --coherent camera|shadow|both|none are its alternatives. Both modes write the same image for one seed.
//
// Geometry is what a fair Embree renderer would build: boxes as 12 triangles each (one triangle geometry),
// spheres as Embree's native RTC_GEOMETRY_TYPE_SPHERE_POINT (exact ray–sphere tests, no tessellation),
// and the visible area-light rectangles as two triangles each in a geometry with its own ray mask, so
// camera rays see them and shadow rays do not (SPEC §5: lights cast no shadow).
//
// Usage: embree_render SCENE [--mode single|stream] [--threads N] [--seed S] [--samples-per-cell K]
//                            [--width W --height H] -o OUT.pfm
#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "embree_render.h"
#include "image/image_writer.h"
#include "scene/scene_reader.h"

namespace embree_peer {
namespace {

struct Options {
    std::string scene, out = "embree.pfm";
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    uint64_t seed = 1;
    int samplesPerCell = 1;
    int width = 0, height = 0;  // 0: the scene's
    bool stream = false;
    int packet = 16;
    ShadowStream shadowStream = ShadowStream::OneM;
    std::string coherent = "both";
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
        else if (a == "--mode" && (v = value()) && (!std::strcmp(v, "single") || !std::strcmp(v, "stream")))
            o.stream = !std::strcmp(v, "stream");
        else if (a == "--packet" && (v = value()) && (!std::strcmp(v, "1") || !std::strcmp(v, "4") || !std::strcmp(v, "8") || !std::strcmp(v, "16")))
            o.packet = std::atoi(v);
        else if (a == "--shadow-stream" && (v = value()) && (!std::strcmp(v, "np") || !std::strcmp(v, "1m")))
            o.shadowStream = !std::strcmp(v, "np") ? ShadowStream::Np : ShadowStream::OneM;
        else if (a == "--coherent" && (v = value()) &&
                 (!std::strcmp(v, "camera") || !std::strcmp(v, "shadow") || !std::strcmp(v, "both") || !std::strcmp(v, "none")))
            o.coherent = v;
        else if (!a.empty() && a[0] != '-' && o.scene.empty()) o.scene = a;
        else return false;
    }
    return !o.scene.empty();
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

}  // namespace

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

}  // namespace embree_peer

int main(int argc, char** argv) {
    using namespace embree_peer;
    using trazo::Vec3;
    Options opt;
    if (!parseOptions(argc, argv, opt)) {
        std::fprintf(stderr, "usage: embree_render SCENE [--mode single|stream] [--threads N] [--seed S] "
                             "[--samples-per-cell K] [--width W --height H] [-o OUT.pfm]\n"
                             "  stream mode: [--packet 1|4|8|16] [--shadow-stream 1m|np] [--coherent camera|shadow|both|none]\n");
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
    job.packet = opt.packet, job.shadowStream = opt.shadowStream;
    job.coherentCamera = opt.coherent == "camera" || opt.coherent == "both";
    job.coherentShadows = opt.coherent == "shadow" || opt.coherent == "both";
    std::vector<Vec3> image((size_t)job.width * job.height);
    job.image = &image;

    const auto renderStart = Clock::now();
    std::vector<std::thread> workers;
    for (unsigned i = 0; i < opt.threads; ++i) workers.emplace_back(opt.stream ? renderTilesStream : renderTilesSingle, std::ref(job));
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
    const std::string mode = !opt.stream ? "single (rtcIntersect1, rtcOccluded1)"
        : "stream (rtcIntersect" + std::to_string(opt.packet) + " over 8x8 tiles, " +
              (opt.shadowStream == ShadowStream::Np ? "rtcOccludedNp" : "rtcOccluded1M") + " per tile, coherent " +
              opt.coherent + ")";
    std::printf("build %.4f s, render %.4f s, %llu rays, %.2f Mrays/s, %d x %d, %u threads, %d sample(s) per cell, "
                "mode %s\n",
                buildSeconds, renderSeconds, (unsigned long long)rays, rays / renderSeconds * 1e-6, job.width,
                job.height, opt.threads, opt.samplesPerCell, mode.c_str());
    return 0;
}
