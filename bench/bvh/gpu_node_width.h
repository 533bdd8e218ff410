// bvh_bench's node-width experiment on the GPU: one mesh's rays traced over its four-wide BVH (the renderer's
// device traversal), over the eight-wide nodes the CPU's AVX2/AVX-512 kernels use, and over those nodes with
// quantized boxes (device traversals of their own, in gpu_node_width.cu), kernel time each, answers compared.
// It decides which node format would pay on the device (issue 25); the renderer's kernels stay four-wide unless
// it says so.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "accel/wide_bvh_node.h"
#include "geometry/intersect_triangle_leaf.h"
#include "integrator/ray_query.h"

namespace trazo {

// The node formats, in GpuNodeWidthTiming's arrays: four-wide (the renderer's), eight-wide (WideBvhNode8),
// eight-wide with its child boxes quantized to 8 bits (96 bytes a node, gpu_node_width.cu).
constexpr int kNodeFormats = 3;
constexpr const char* kNodeFormatNames[kNodeFormats] = {"four-wide", "eight-wide", "eight-wide quantized"};

struct GpuNodeWidthTiming {
    bool ran = false;
    std::string why;                          // when it did not run
    double seconds[kNodeFormats] = {};        // best kernel time over the repeats
    size_t agree[kNodeFormats] = {};          // rays answered bit for bit as over four-wide nodes
    size_t stackOverflows[kNodeFormats] = {}; // rays that dropped a push for want of stack (then may differ)
};

// Nearest t (or blocked, for shadow rays) of each query over the mesh's nodes; the triangles in leaf order.
GpuNodeWidthTiming timeGpuNodeWidths(const std::vector<WideBvhNode>& nodes4, const std::vector<WideBvhNode8>& nodes8,
                                     const std::vector<MeshTriangle>& triangles, const std::vector<RayQuery>& rays,
                                     bool shadow, int repeat);

}  // namespace trazo
