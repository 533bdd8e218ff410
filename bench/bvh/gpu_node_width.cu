// The GPU side of bvh_bench's node-width experiment (gpu_node_width.h). Both kernels test leaves as
// intersectMesh does (the renderer's triangle test, the lower triangle index winning ties), so their answers
// must agree bit for bit; only the node format and its traversal differ.
#include "gpu_node_width.h"

#include <cuda_runtime.h>

#include <algorithm>
#include <cmath>

#include "accel/bvh_traverse.h"

namespace trazo {
namespace {

// The ray as an eight-wide traversal tests boxes: which plane of each slab it meets first, settled once.
struct DeviceNodeRay8 {
    BoxRay box;
    int nearSide[3];
};

__device__ DeviceNodeRay8 makeDeviceNodeRay8(const Ray& ray) {
    DeviceNodeRay8 r{makeBoxRay(ray), {}};
    for (int axis = 0; axis < 3; ++axis) r.nearSide[axis] = r.box.invDirection[axis] < 0.0f ? 1 : 0;
    return r;
}

// intersectChildrenScalar's slab test for one lane of an eight-wide node: whether the ray meets that child's box
// within (tMin, tMax), entering at tEntry.
__device__ bool entersChild(const DeviceNodeRay8& r, const WideBvhNode8& node, int lane, float tMin, float tMax,
                            float& tEntry) {
    float t0 = tMin, t1 = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        const float origin = r.box.origin[axis], inv = r.box.invDirection[axis];
        const float tNear = (node.bounds[axis][r.nearSide[axis]][lane] - origin) * inv;
        const float tFar = (node.bounds[axis][1 - r.nearSide[axis]][lane] - origin) * inv;
        t0 = tNear > t0 ? tNear : t0;
        t1 = tFar < t1 ? tFar : t1;
    }
    tEntry = t0;
    return t0 <= t1 * kBoxExitScale;
}

// The eight-wide closest-hit traversal a device would run: intersectChildrenScalar's slab test for eight
// lanes, the children entered sorted by entry (nearest taken, the rest pushed farthest first), popped
// children skipped once a nearer hit is known. `overflows` counts pushes dropped for want of stack.
template <class LeafFn>
__device__ bool traverseClosest8Device(const WideBvhNode8* nodes, const Ray& ray, float tMin, float& tMax,
                                       bvh_detail::StackEntry* entries, int capacity, unsigned& overflows,
                                       LeafFn&& leaf) {
    using bvh_detail::StackEntry;
    const DeviceNodeRay8 r = makeDeviceNodeRay8(ray);
    int size = 0;
    uint32_t ref = 0;
    bool hit = false;
    for (;;) {
        if (!bvhIsLeaf(ref)) {
            const WideBvhNode8& node = nodes[ref];
            StackEntry hits[kBvh8Width];
            int count = 0;
            for (int lane = 0; lane < kBvh8Width; ++lane) {
                const uint32_t child = node.child[lane];
                float t0;
                if (child == kBvhEmptyLane || !entersChild(r, node, lane, tMin, tMax, t0)) continue;
                int i = count++;
                for (; i > 0 && hits[i - 1].tEntry < t0; --i) hits[i] = hits[i - 1];
                hits[i] = StackEntry{child, t0};
            }
            if (count > 0) {
                for (int i = 0; i < count - 1; ++i) {
                    if (size < capacity) entries[size++] = hits[i];
                    else ++overflows;
                }
                ref = hits[count - 1].ref;
                continue;
            }
        } else if (leaf(bvhLeafFirst(ref), bvhLeafCount(ref), tMax)) {
            hit = true;
        }
        for (;;) {
            if (size == 0) return hit;
            const StackEntry e = entries[--size];
            if (e.tEntry <= tMax * kBoxExitScale) {
                ref = e.ref;
                break;
            }
        }
    }
}

// Any hit over eight-wide nodes: the first child entered taken, the others pushed.
template <class LeafFn>
__device__ bool traverseAny8Device(const WideBvhNode8* nodes, const Ray& ray, float tMin, float tMax,
                                   uint32_t* entries, int capacity, unsigned& overflows, LeafFn&& leaf) {
    const DeviceNodeRay8 r = makeDeviceNodeRay8(ray);
    int size = 0;
    uint32_t ref = 0;
    for (;;) {
        if (!bvhIsLeaf(ref)) {
            const WideBvhNode8& node = nodes[ref];
            uint32_t first = kBvhEmptyLane;
            for (int lane = 0; lane < kBvh8Width; ++lane) {
                const uint32_t child = node.child[lane];
                float t0;
                if (child == kBvhEmptyLane || !entersChild(r, node, lane, tMin, tMax, t0)) continue;
                if (first == kBvhEmptyLane) first = child;
                else if (size < capacity) entries[size++] = child;
                else ++overflows;
            }
            if (first != kBvhEmptyLane) {
                ref = first;
                continue;
            }
        } else if (leaf(bvhLeafFirst(ref), bvhLeafCount(ref), tMax)) {
            return true;
        }
        if (size == 0) return false;
        ref = entries[--size];
    }
}

// intersectMesh's leaf: the nearest triangle, of equal ones the first in the mesh's order.
struct NearestLeaf {
    const TriangleRay& tr;
    const MeshTriangle* triangles;
    uint32_t best = 0;
    TriangleHit bestHit{};
    __device__ bool operator()(uint32_t first, uint32_t count, float& tNearest) {
        const float tLimit = first < best ? nextFloatUp(tNearest) : tNearest;
        uint32_t which = 0;
        if (!intersectTriangleLeaf(tr, triangles + first, count, 0.0f, tLimit, bestHit, which)) return false;
        tNearest = bestHit.t;
        best = first + which;
        return true;
    }
};

constexpr int kStack = kDeviceTraversalStackSize;

template <int Width>
__global__ void nearestKernel(const void* nodes, const MeshTriangle* triangles, const RayQuery* queries,
                              uint32_t count, float* out, unsigned* overflows) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    const RayQuery q = queries[i];
    const TriangleRay tr = makeTriangleRay(q.ray);
    NearestLeaf leaf{tr, triangles};
    float t = q.tMax;
    bool hit;
    bvh_detail::StackEntry entries[kStack];
    if constexpr (Width == 4) {
        ClosestStack stack{entries, kStack, 0};
        hit = traverseClosest(static_cast<const WideBvhNode*>(nodes), q.ray, 0.0f, t, stack, leaf);
    } else {
        unsigned dropped = 0;
        hit = traverseClosest8Device(static_cast<const WideBvhNode8*>(nodes), q.ray, 0.0f, t, entries, kStack, dropped,
                                     leaf);
        if (dropped) atomicAdd(overflows, 1u);
    }
    out[i] = hit ? t : INFINITY;
}

template <int Width>
__global__ void shadowKernel(const void* nodes, const MeshTriangle* triangles, const RayQuery* queries,
                             uint32_t count, float* out, unsigned* overflows) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    const RayQuery q = queries[i];
    const TriangleRay tr = makeTriangleRay(q.ray);
    auto leaf = [&](uint32_t first, uint32_t n, float tLimit) {
        return triangleLeafBlocks(tr, triangles + first, n, 0.0f, tLimit);
    };
    uint32_t entries[kStack];
    bool blocked;
    if constexpr (Width == 4) {
        AnyStack stack{entries, kStack, 0};
        blocked = traverseAny(static_cast<const WideBvhNode*>(nodes), q.ray, 0.0f, q.tMax, stack, leaf);
    } else {
        unsigned dropped = 0;
        blocked = traverseAny8Device(static_cast<const WideBvhNode8*>(nodes), q.ray, 0.0f, q.tMax, entries, kStack,
                                     dropped, leaf);
        if (dropped) atomicAdd(overflows, 1u);
    }
    out[i] = blocked ? 1.0f : 0.0f;
}

template <class T>
struct Buffer {
    T* data = nullptr;
    ~Buffer() { cudaFree(data); }
    cudaError_t upload(const std::vector<T>& v) {
        cudaError_t e = cudaMalloc(&data, std::max<size_t>(1, v.size()) * sizeof(T));
        return e != cudaSuccess ? e : cudaMemcpy(data, v.data(), v.size() * sizeof(T), cudaMemcpyHostToDevice);
    }
    cudaError_t allocate(size_t n) { return cudaMalloc(&data, std::max<size_t>(1, n) * sizeof(T)); }
};

}  // namespace

GpuNodeWidthTiming timeGpuNodeWidths(const std::vector<WideBvhNode>& nodes4, const std::vector<WideBvhNode8>& nodes8,
                                     const std::vector<MeshTriangle>& triangles, const std::vector<RayQuery>& rays,
                                     bool shadow, int repeat) {
    GpuNodeWidthTiming result;
    int devices = 0;
    if (cudaGetDeviceCount(&devices) != cudaSuccess || devices == 0) {
        result.why = "no CUDA device";
        return result;
    }
    Buffer<WideBvhNode> n4;
    Buffer<WideBvhNode8> n8;
    Buffer<MeshTriangle> tris;
    Buffer<RayQuery> queries;
    Buffer<float> out4, out8;
    Buffer<unsigned> overflows;
    cudaError_t e = cudaSuccess;
    auto check = [&](cudaError_t status) {
        if (e == cudaSuccess) e = status;
    };
    check(n4.upload(nodes4));
    check(n8.upload(nodes8));
    check(tris.upload(triangles));
    check(queries.upload(rays));
    check(out4.allocate(rays.size()));
    check(out8.allocate(rays.size()));
    check(overflows.upload(std::vector<unsigned>{0u}));
    cudaEvent_t start, stop;
    check(cudaEventCreate(&start));
    check(cudaEventCreate(&stop));
    if (e != cudaSuccess) {
        result.why = cudaGetErrorString(e);
        return result;
    }
    const uint32_t count = (uint32_t)rays.size();
    const unsigned threads = 128, blocks = (count + threads - 1) / threads;
    auto launch = [&](int width) {
        const void* nodes = width == 4 ? static_cast<const void*>(n4.data) : static_cast<const void*>(n8.data);
        float* out = width == 4 ? out4.data : out8.data;
        if (shadow) {
            if (width == 4) shadowKernel<4><<<blocks, threads>>>(nodes, tris.data, queries.data, count, out, overflows.data);
            else shadowKernel<8><<<blocks, threads>>>(nodes, tris.data, queries.data, count, out, overflows.data);
        } else {
            if (width == 4) nearestKernel<4><<<blocks, threads>>>(nodes, tris.data, queries.data, count, out, overflows.data);
            else nearestKernel<8><<<blocks, threads>>>(nodes, tris.data, queries.data, count, out, overflows.data);
        }
    };
    double best[2] = {1e30, 1e30};
    for (int r = 0; r < std::max(1, repeat) + 1; ++r) {  // the first round warms up, untimed
        for (int w = 0; w < 2; ++w) {
            if (w == 1) check(cudaMemset(overflows.data, 0, sizeof(unsigned)));  // counted for the last launch
            check(cudaEventRecord(start));
            launch(w == 0 ? 4 : 8);
            check(cudaGetLastError());
            check(cudaEventRecord(stop));
            check(cudaEventSynchronize(stop));
            float ms = 0.0f;
            check(cudaEventElapsedTime(&ms, start, stop));
            if (r > 0) best[w] = std::min(best[w], ms * 1e-3);
        }
    }
    std::vector<float> a(count), b(count);
    unsigned dropped = 0;
    check(cudaMemcpy(a.data(), out4.data, count * sizeof(float), cudaMemcpyDeviceToHost));
    check(cudaMemcpy(b.data(), out8.data, count * sizeof(float), cudaMemcpyDeviceToHost));
    check(cudaMemcpy(&dropped, overflows.data, sizeof(unsigned), cudaMemcpyDeviceToHost));
    cudaEventDestroy(start);
    cudaEventDestroy(stop);
    if (e != cudaSuccess) {
        result.why = cudaGetErrorString(e);
        return result;
    }
    result.ran = true;
    result.seconds4 = best[0];
    result.seconds8 = best[1];
    result.stackOverflows = dropped;
    for (uint32_t i = 0; i < count; ++i) result.agree += a[i] == b[i] || (std::isinf(a[i]) && std::isinf(b[i]));
    return result;
}

}  // namespace trazo
