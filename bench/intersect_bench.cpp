// Google Benchmark micro-benchmarks of the ray–shape intersection routines (rays per second each).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "objects/box.h"
#include "objects/cylinder.h"
#include "objects/sphere.h"

namespace {

using namespace trazo;

// Rays from a cube around the shapes, aimed near the centre (mostly hits) or anywhere (mostly misses,
// like the shadow and secondary rays of a scene, where most rays miss most objects).
std::vector<Ray> randomRays(size_t n, bool aimed) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<Ray> rays(n);
    for (Ray& r : rays) {
        r.origin = Vec3(u(rng), u(rng), u(rng)) * 4.0f;
        r.direction = aimed ? normalize(Vec3(u(rng), u(rng), u(rng)) * 0.5f - r.origin)
                            : normalize(Vec3(u(rng), u(rng), u(rng)));
    }
    return rays;
}

template <typename Shape, bool (*Intersect)(const Shape&, const Ray&, float, float, ShapeHit&)>
void runIntersections(benchmark::State& state, const Shape& shape) {
    const std::vector<Ray> rays = randomRays(4096, state.range(0) != 0);
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

// Argument: 1 = aimed rays (mostly hits), 0 = random rays (mostly misses).
BENCHMARK(BM_Sphere)->Arg(1)->Arg(0);
BENCHMARK(BM_Box)->Arg(1)->Arg(0);
BENCHMARK(BM_Cylinder)->Arg(1)->Arg(0);

}  // namespace
