// Google Benchmark micro-benchmarks of the ray–shape intersection routines (rays per second each).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "geometry/intersect_box.h"
#include "geometry/intersect_cylinder.h"
#include "geometry/intersect_sphere.h"

namespace {

using namespace trazo;

std::vector<Ray> randomRays(size_t n) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<Ray> rays(n);
    for (Ray& r : rays) {
        r.origin = Vec3(u(rng), u(rng), u(rng)) * 4.0f;
        r.direction = normalize(Vec3(u(rng), u(rng), u(rng)) * 0.5f - r.origin);
    }
    return rays;
}

template <typename Shape, bool (*Intersect)(const Shape&, const Ray&, float, float, ShapeHit&)>
void runIntersections(benchmark::State& state, const Shape& shape) {
    const std::vector<Ray> rays = randomRays(4096);
    size_t hits = 0;
    for (auto _ : state) {
        for (const Ray& r : rays) {
            ShapeHit h;
            hits += Intersect(shape, r, 0.0f, INFINITY, h);
        }
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(int64_t(state.iterations()) * rays.size());
}

void BM_Sphere(benchmark::State& state) {
    runIntersections<SphereShape, intersectSphere>(state, SphereShape{Vec3(0.0f), 1.0f});
}
void BM_Box(benchmark::State& state) {
    const Affine3 m = then(makeScale(Vec3(2, 1, 1)), makeRotation(Vec3(1, 1, 0), 0.4f));
    runIntersections<BoxShape, intersectBox>(state, BoxShape{inverse(m), m});
}
void BM_Cylinder(benchmark::State& state) {
    runIntersections<CylinderShape, intersectCylinder>(state, CylinderShape{Vec3(0, -1, 0), Vec3(0, 1, 0), 2.0f, 1.0f});
}

BENCHMARK(BM_Sphere);
BENCHMARK(BM_Box);
BENCHMARK(BM_Cylinder);

}  // namespace
