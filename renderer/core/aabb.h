// Aabb: the axis-aligned bounding box of the host side (BVH builds, object and CSG bounds, the viewer's
// framing); an empty box has min = +inf, max = −inf.
#pragma once

#include <limits>

#include "core/vec3.h"

namespace trazo {

struct Aabb {
    Vec3 min{std::numeric_limits<float>::infinity()};
    Vec3 max{-std::numeric_limits<float>::infinity()};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void grow(Vec3 p) {
        min = trazo::min(min, p);
        max = trazo::max(max, p);
    }
    void grow(const Aabb& b) {
        min = trazo::min(min, b.min);
        max = trazo::max(max, b.max);
    }
    Vec3 centroid() const { return (min + max) * 0.5f; }
    Vec3 extent() const { return max - min; }
    // 0 for an empty box, so empty children cost nothing in the SAH.
    float surfaceArea() const {
        if (empty()) return 0.0f;
        const Vec3 e = extent();
        return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
    // Grown by a relative margin (a hundred-thousandth of the extent, a millionth of the corners' magnitudes) so
    // that rounding in a slab test never culls a ray the shape's own exact test would hit. Empty boxes come
    // back as the canonical empty box, which every slab test misses.
    Aabb padded() const {
        if (empty()) return Aabb{};
        const Vec3 pad = abs(max - min) * 1e-5f + abs(max) * 1e-6f + abs(min) * 1e-6f;
        return Aabb{min - pad, max + pad};
    }
    bool contains(const Aabb& b) const {
        return min.x <= b.min.x && min.y <= b.min.y && min.z <= b.min.z && max.x >= b.max.x &&
               max.y >= b.max.y && max.z >= b.max.z;
    }
};

inline Aabb triangleBounds(Vec3 p0, Vec3 p1, Vec3 p2) {
    Aabb b;
    b.grow(p0);
    b.grow(p1);
    b.grow(p2);
    return b;
}

}  // namespace trazo
