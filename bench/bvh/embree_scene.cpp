// The Embree 3 side of bvh_bench (default build quality, rtcIntersect1 / rtcOccluded1).
#include "embree_scene.h"

#include <embree3/rtcore.h>

#include <chrono>
#include <cmath>
#include <string>

namespace trazo::bench {

struct EmbreeScene::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
};

EmbreeScene::EmbreeScene(const std::vector<Vec3>& triangles, unsigned threads, bool printStatistics)
    : impl_(new Impl) {
    std::string config = threads ? "threads=" + std::to_string(threads) : "";
    if (printStatistics) config += config.empty() ? "verbose=2" : ",verbose=2";
    impl_->device = rtcNewDevice(config.c_str());
    const auto start = std::chrono::steady_clock::now();
    impl_->scene = rtcNewScene(impl_->device);
    RTCGeometry geometry = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    const size_t count = triangles.size() / 3;
    auto* vertices = (float*)rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                     3 * sizeof(float), triangles.size());
    auto* indices = (unsigned*)rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                       3 * sizeof(unsigned), count);
    for (size_t i = 0; i < triangles.size(); ++i) {
        vertices[3 * i] = triangles[i].x;
        vertices[3 * i + 1] = triangles[i].y;
        vertices[3 * i + 2] = triangles[i].z;
        indices[i] = (unsigned)i;
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(impl_->scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(impl_->scene);
    buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

EmbreeScene::~EmbreeScene() {
    rtcReleaseScene(impl_->scene);
    rtcReleaseDevice(impl_->device);
}

float EmbreeScene::intersect(const Ray& ray, float tMin, float tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = ray.origin.x, rh.ray.org_y = ray.origin.y, rh.ray.org_z = ray.origin.z;
    rh.ray.dir_x = ray.direction.x, rh.ray.dir_y = ray.direction.y, rh.ray.dir_z = ray.direction.z;
    rh.ray.tnear = tMin;
    rh.ray.tfar = tMax;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->scene, &context, &rh);
    return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? INFINITY : rh.ray.tfar;
}

bool EmbreeScene::occluded(const Ray& ray, float tMin, float tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r{};
    r.org_x = ray.origin.x, r.org_y = ray.origin.y, r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x, r.dir_y = ray.direction.y, r.dir_z = ray.direction.z;
    r.tnear = tMin;
    r.tfar = tMax;
    r.mask = ~0u;
    rtcOccluded1(impl_->scene, &context, &r);
    return r.tfar < 0.0f;  // Embree sets tfar = −inf on an occlusion
}

}  // namespace trazo::bench
