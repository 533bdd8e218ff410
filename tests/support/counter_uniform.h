// CounterUniform: uniform numbers from a seed and a running counter, through the kernels' hash, so generated
// meshes and test inputs are the same on every platform (host code).
#pragma once

#include <cstdint>

#include "core/rng.h"
#include "core/vec3.h"

namespace trazo {

struct CounterUniform {
    uint32_t key, counter = 0;
    explicit CounterUniform(uint32_t seed) : key(hashU32(seed)) {}
    // Uniform in [lo, hi).
    float operator()(float lo, float hi) { return lo + (hi - lo) * bitsToUnitFloat(hashCombine(key, counter++)); }
    // Uniform in the cube [−size, size]³.
    Vec3 point(float size) { return {(*this)(-size, size), (*this)(-size, size), (*this)(-size, size)}; }
    // A uniform unit vector (cube points rejected outside the unit ball or too near its centre).
    Vec3 direction() {
        for (;;) {
            const Vec3 p = point(1.0f);
            if (lengthSquared(p) > 1e-4f && lengthSquared(p) <= 1.0f) return normalize(p);
        }
    }
};

}  // namespace trazo
