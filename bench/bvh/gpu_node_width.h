// bvh_bench's node-width experiment on the GPU: one mesh's rays traced over its four-wide BVH (the renderer's
// device traversal) and over the eight-wide nodes the CPU's AVX2/AVX-512 kernels use (a device traversal of
// its own, in gpu_node_width.cu), kernel time each, answers compared. It decides whether those nodes would pay
// on the device (issue 25); the renderer's kernels stay four-wide unless it says so.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "accel/wide_bvh_node.h"
#include "geometry/intersect_triangle_leaf.h"
#include "integrator/ray_query.h"

namespace trazo {

struct GpuNodeWidthTiming {
    bool ran = false;
    std::string why;            // when it did not run
    double seconds4 = 0.0;      // best kernel time over the repeats, four-wide nodes
    double seconds8 = 0.0;      // the same, eight-wide nodes
    size_t agree = 0;           // rays whose answers are bit for bit the same over both
    size_t stackOverflows = 0;  // eight-wide pushes dropped for want of stack (answers may then differ)
};

// Nearest t (or blocked, for shadow rays) of each query over the mesh's nodes; the triangles in leaf order.
GpuNodeWidthTiming timeGpuNodeWidths(const std::vector<WideBvhNode>& nodes4, const std::vector<WideBvhNode8>& nodes8,
                                     const std::vector<MeshTriangle>& triangles, const std::vector<RayQuery>& rays,
                                     bool shadow, int repeat);

}  // namespace trazo
