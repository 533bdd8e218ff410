// Generated triangle meshes for tests and benchmarks (host). Every function returns a triangle list:
// 3 consecutive positions per triangle (triangle i = p[3i], p[3i+1], p[3i+2]).
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace trazo {

// A closed latitude–longitude sphere: `rings` ≥ 2 bands between the poles, `segments` ≥ 3 around, one
// vertex per pole (triangle fans, so no zero-area triangles), 2·segments·(rings − 1) triangles, wound
// counter-clockwise seen from outside. Each vertex is computed once and copied into every triangle that
// uses it, so neighbouring triangles share bitwise-equal corners and watertightness is well defined.
// bumpAmplitude > 0 displaces the radius by a smooth pseudo-random sum of sines (relative amplitude).
std::vector<Vec3> tessellateSphere(Vec3 center, float radius, uint32_t rings, uint32_t segments,
                                   float bumpAmplitude = 0.0f);

// `count` triangles with corners uniform in the cube [−size, size]³ (deterministic for a seed).
std::vector<Vec3> randomTriangleSoup(uint32_t count, uint32_t seed, float size = 1.0f);

// `count` hard cases in [−1, 1]³, cycling through: all three corners equal, two corners equal, three
// collinear corners, and slivers (one corner 1e-4 of the edge length off the opposite edge).
std::vector<Vec3> degenerateTriangles(uint32_t count, uint32_t seed);

}  // namespace trazo
