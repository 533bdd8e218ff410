// The Embree 3 side of bvh_bench: the same triangles in an Embree scene, traced one ray at a time.
#pragma once

#include <memory>
#include <vector>

#include "core/ray.h"

namespace trazo::bench {

class EmbreeScene {
public:
    // threads = 0: Embree's default (all cores) for its build. printStatistics: Embree prints its device banner and
    // its BVH's statistics as it builds (device option verbose=2): "getAABBNodes sah" is a ray's expected node
    // visits, "leaves sah" its expected leaf-block tests (Σ area over the root's).
    EmbreeScene(const std::vector<Vec3>& triangles, unsigned threads, bool printStatistics = false);
    ~EmbreeScene();
    double buildSeconds() const { return buildSeconds_; }
    // Nearest hit distance within (tMin, tMax), or +inf on a miss.
    float intersect(const Ray& ray, float tMin, float tMax) const;
    bool occluded(const Ray& ray, float tMin, float tMax) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    double buildSeconds_ = 0.0;
};

}  // namespace trazo::bench
