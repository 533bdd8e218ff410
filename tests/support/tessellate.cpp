// Generated triangle meshes for tests and benchmarks (host).
#include "support/tessellate.h"

#include <cmath>

#include "support/counter_uniform.h"

namespace trazo {
namespace {

constexpr float kPi = 3.14159265358979f;

}  // namespace

std::vector<Vec3> tessellateSphere(Vec3 center, float radius, uint32_t rings, uint32_t segments, float bumpAmplitude) {
    rings = rings < 2 ? 2 : rings;
    segments = segments < 3 ? 3 : segments;
    // Vertex grid: the north pole, (rings − 1) latitude circles of `segments` vertices, the south pole.
    std::vector<Vec3> vertices;
    vertices.reserve(2 + (size_t)(rings - 1) * segments);
    auto place = [&](float theta, float phi) {
        const Vec3 dir(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
        float r = radius;
        if (bumpAmplitude > 0.0f)
            r *= 1.0f + bumpAmplitude * (0.5f * std::sin(7.0f * dir.x + 3.0f * dir.y) +
                                         0.3f * std::sin(19.0f * dir.y - 11.0f * dir.z) +
                                         0.2f * std::sin(53.0f * dir.z + 41.0f * dir.x));
        vertices.push_back(center + dir * r);
    };
    place(0.0f, 0.0f);
    for (uint32_t i = 1; i < rings; ++i)
        for (uint32_t j = 0; j < segments; ++j) place(kPi * (float)i / (float)rings, 2.0f * kPi * (float)j / (float)segments);
    place(kPi, 0.0f);
    const uint32_t south = (uint32_t)vertices.size() - 1;
    auto ringVertex = [&](uint32_t ring, uint32_t segment) { return 1 + (ring - 1) * segments + segment % segments; };

    std::vector<Vec3> triangles;
    triangles.reserve((size_t)6 * segments * (rings - 1));
    auto emit = [&](uint32_t a, uint32_t b, uint32_t c) {
        triangles.push_back(vertices[a]);
        triangles.push_back(vertices[b]);
        triangles.push_back(vertices[c]);
    };
    // With y up and phi growing from +x towards +z, (north, j+1, j) is counter-clockwise from outside.
    for (uint32_t j = 0; j < segments; ++j) emit(0, ringVertex(1, j + 1), ringVertex(1, j));
    for (uint32_t i = 1; i + 1 < rings; ++i)
        for (uint32_t j = 0; j < segments; ++j) {
            const uint32_t a = ringVertex(i, j), b = ringVertex(i, j + 1);
            const uint32_t c = ringVertex(i + 1, j), d = ringVertex(i + 1, j + 1);
            emit(a, b, d);
            emit(a, d, c);
        }
    for (uint32_t j = 0; j < segments; ++j) emit(south, ringVertex(rings - 1, j), ringVertex(rings - 1, j + 1));
    return triangles;
}

std::vector<Vec3> randomTriangleSoup(uint32_t count, uint32_t seed, float size) {
    CounterUniform u(seed ^ 0x2545f491u);
    std::vector<Vec3> triangles;
    triangles.reserve((size_t)3 * count);
    for (uint32_t i = 0; i < 3 * count; ++i) triangles.push_back(u.point(size));
    return triangles;
}

std::vector<Vec3> degenerateTriangles(uint32_t count, uint32_t seed) {
    CounterUniform u(seed ^ 0x2545f491u);
    std::vector<Vec3> triangles;
    triangles.reserve((size_t)3 * count);
    for (uint32_t i = 0; i < count; ++i) {
        const Vec3 a = u.point(1.0f), b = u.point(1.0f);
        Vec3 c;
        switch (i % 4) {
            case 0: triangles.insert(triangles.end(), {a, a, a}); continue;
            case 1: triangles.insert(triangles.end(), {a, b, a}); continue;
            case 2: c = lerp(a, b, u(-0.5f, 1.5f)); break;  // collinear up to rounding
            default: {
                // A sliver: the third corner barely off the edge ab.
                const Vec3 off = cross(b - a, u.point(1.0f));
                c = lerp(a, b, u(0.0f, 1.0f)) + off * (1e-4f * length(b - a) / (length(off) + 1e-30f));
            }
        }
        triangles.insert(triangles.end(), {a, b, c});
    }
    return triangles;
}

}  // namespace trazo
