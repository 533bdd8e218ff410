// The GPU side of bvh_bench's node-format experiment (gpu_node_width.h). Every kernel tests leaves as
// intersectMesh does (the renderer's triangle test, the lower triangle index winning ties), so their answers
// must agree bit for bit; only the node format and its traversal differ.
#include "gpu_node_width.h"

#include <cuda_runtime.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

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

__device__ int laneCount(const WideBvhNode8&) { return kBvh8Width; }

// An eight-wide node with its children's boxes quantized to 8 bits an axis, relative to the node's box and a
// power-of-two step per axis, rounded outwards (so a ray meets at least the boxes it met, and the leaves answer
// as before): 96 bytes, three 32-byte sectors, against 128 for a four-wide node and 256 for WideBvhNode8. After
// Ylitie, Karras and Laine (2017), simpler: full child references, no node or triangle groups.
struct alignas(32) CompressedNode8 {
    float origin[3];                 // the node's box min
    int8_t exponent[3];              // per axis, the step 2^exponent
    uint8_t count;                   // children in use, lanes [0, count)
    uint32_t child[kBvh8Width];      // as WideBvhNode8's (interior: an index into the same array)
    uint8_t lo[3][kBvh8Width];       // child box min = origin + lo * step
    uint8_t hi[3][kBvh8Width];       // child box max = origin + hi * step
};
static_assert(sizeof(CompressedNode8) == 96, "three 32-byte sectors");

// 2^e for the exponents compressNodes8 picks (normal floats): built from its bits, as the device does.
__host__ __device__ float stepOf(int e) {
    const uint32_t bits = uint32_t(e + 127) << 23;
    float f;
    memcpy(&f, &bits, sizeof f);
    return f;
}

// origin + q · step: the product is exact (q < 2^8, step a power of two), so one rounding, with or without
// contraction into an FMA: host and device get the same float.
__host__ __device__ float dequantize(float origin, uint8_t q, float step) { return origin + float(q) * step; }

__device__ int laneCount(const CompressedNode8& node) { return node.count; }

__device__ bool entersChild(const DeviceNodeRay8& r, const CompressedNode8& node, int lane, float tMin, float tMax,
                            float& tEntry) {
    float t0 = tMin, t1 = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        const float step = stepOf(node.exponent[axis]);
        const float lo = dequantize(node.origin[axis], node.lo[axis][lane], step),
                    hi = dequantize(node.origin[axis], node.hi[axis][lane], step);
        const float origin = r.box.origin[axis], inv = r.box.invDirection[axis];
        const float tNear = ((r.nearSide[axis] ? hi : lo) - origin) * inv;
        const float tFar = ((r.nearSide[axis] ? lo : hi) - origin) * inv;
        t0 = tNear > t0 ? tNear : t0;
        t1 = tFar < t1 ? tFar : t1;
    }
    tEntry = t0;
    return t0 <= t1 * kBoxExitScale;
}

// The nodes compressed, one for one (so interior references stay valid); lanes in use moved to the front.
std::vector<CompressedNode8> compressNodes8(const std::vector<WideBvhNode8>& nodes) {
    std::vector<CompressedNode8> out(nodes.size());
    for (size_t n = 0; n < nodes.size(); ++n) {
        const WideBvhNode8& node = nodes[n];
        CompressedNode8& c = out[n];
        int used[kBvh8Width], count = 0;
        for (int lane = 0; lane < kBvh8Width; ++lane)
            if (node.child[lane] != kBvhEmptyLane) used[count++] = lane;
        c.count = (uint8_t)count;
        for (int k = 0; k < kBvh8Width; ++k) c.child[k] = k < count ? node.child[used[k]] : kBvhEmptyLane;
        for (int axis = 0; axis < 3; ++axis) {
            float lo = INFINITY, hi = -INFINITY;
            for (int k = 0; k < count; ++k) {
                lo = std::min(lo, node.bounds[axis][0][used[k]]);
                hi = std::max(hi, node.bounds[axis][1][used[k]]);
            }
            if (count == 0) lo = hi = 0.0f;
            c.origin[axis] = lo;
            int e = hi > lo ? std::max(-100, (int)std::ceil(std::log2((double(hi) - lo) / 255.0))) : -100;
            while (dequantize(lo, 255, stepOf(e)) < hi) ++e;
            c.exponent[axis] = (int8_t)e;
            const float step = stepOf(e);
            for (int k = 0; k < kBvh8Width; ++k) {
                if (k >= count) {
                    c.lo[axis][k] = c.hi[axis][k] = 0;
                    continue;
                }
                const float childLo = node.bounds[axis][0][used[k]], childHi = node.bounds[axis][1][used[k]];
                int qLo = std::clamp((int)std::floor((double(childLo) - lo) / step), 0, 255);
                int qHi = std::clamp((int)std::ceil((double(childHi) - lo) / step), 0, 255);
                while (qLo > 0 && dequantize(lo, (uint8_t)qLo, step) > childLo) --qLo;
                while (qHi < 255 && dequantize(lo, (uint8_t)qHi, step) < childHi) ++qHi;
                c.lo[axis][k] = (uint8_t)qLo;
                c.hi[axis][k] = (uint8_t)qHi;
            }
        }
    }
    return out;
}

// The eight-wide closest-hit traversal a device would run: intersectChildrenScalar's slab test for eight
// lanes, the children entered sorted by entry (nearest taken, the rest pushed farthest first), popped
// children skipped once a nearer hit is known. `overflows` counts pushes dropped for want of stack.
template <class Node, class LeafFn>
__device__ bool traverseClosest8Device(const Node* nodes, const Ray& ray, float tMin, float& tMax,
                                       bvh_detail::StackEntry* entries, int capacity, unsigned& overflows,
                                       LeafFn&& leaf) {
    using bvh_detail::StackEntry;
    const DeviceNodeRay8 r = makeDeviceNodeRay8(ray);
    int size = 0;
    uint32_t ref = 0;
    bool hit = false;
    for (;;) {
        if (!bvhIsLeaf(ref)) {
            const Node& node = nodes[ref];
            StackEntry hits[kBvh8Width];
            int count = 0;
            for (int lane = 0, lanes = laneCount(node); lane < lanes; ++lane) {
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
template <class Node, class LeafFn>
__device__ bool traverseAny8Device(const Node* nodes, const Ray& ray, float tMin, float tMax,
                                   uint32_t* entries, int capacity, unsigned& overflows, LeafFn&& leaf) {
    const DeviceNodeRay8 r = makeDeviceNodeRay8(ray);
    int size = 0;
    uint32_t ref = 0;
    for (;;) {
        if (!bvhIsLeaf(ref)) {
            const Node& node = nodes[ref];
            uint32_t first = kBvhEmptyLane;
            for (int lane = 0, lanes = laneCount(node); lane < lanes; ++lane) {
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

template <class Node>
__global__ void nearestKernel(const Node* nodes, const MeshTriangle* triangles, const RayQuery* queries,
                              uint32_t count, float* out, unsigned* overflows) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    const RayQuery q = queries[i];
    const TriangleRay tr = makeTriangleRay(q.ray);
    NearestLeaf leaf{tr, triangles};
    float t = q.tMax;
    bool hit;
    bvh_detail::StackEntry entries[kStack];
    if constexpr (std::is_same_v<Node, WideBvhNode>) {
        ClosestStack stack{entries, kStack, 0};
        hit = traverseClosest(nodes, q.ray, 0.0f, t, stack, leaf);
    } else {
        unsigned dropped = 0;
        hit = traverseClosest8Device(nodes, q.ray, 0.0f, t, entries, kStack, dropped, leaf);
        if (dropped) atomicAdd(overflows, 1u);
    }
    out[i] = hit ? t : INFINITY;
}

template <class Node>
__global__ void shadowKernel(const Node* nodes, const MeshTriangle* triangles, const RayQuery* queries,
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
    if constexpr (std::is_same_v<Node, WideBvhNode>) {
        AnyStack stack{entries, kStack, 0};
        blocked = traverseAny(nodes, q.ray, 0.0f, q.tMax, stack, leaf);
    } else {
        unsigned dropped = 0;
        blocked = traverseAny8Device(nodes, q.ray, 0.0f, q.tMax, entries, kStack, dropped, leaf);
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
    Buffer<CompressedNode8> n8c;
    Buffer<MeshTriangle> tris;
    Buffer<RayQuery> queries;
    Buffer<float> out[kNodeFormats];
    Buffer<unsigned> overflows;
    cudaError_t e = cudaSuccess;
    auto check = [&](cudaError_t status) {
        if (e == cudaSuccess) e = status;
    };
    check(n4.upload(nodes4));
    check(n8.upload(nodes8));
    check(n8c.upload(compressNodes8(nodes8)));
    check(tris.upload(triangles));
    check(queries.upload(rays));
    for (Buffer<float>& o : out) check(o.allocate(rays.size()));
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
    auto launchOne = [&](const auto* nodes, float* answers) {
        if (shadow) shadowKernel<<<blocks, threads>>>(nodes, tris.data, queries.data, count, answers, overflows.data);
        else nearestKernel<<<blocks, threads>>>(nodes, tris.data, queries.data, count, answers, overflows.data);
    };
    auto launch = [&](int format) {
        if (format == 0) launchOne(n4.data, out[0].data);
        else if (format == 1) launchOne(n8.data, out[1].data);
        else launchOne(n8c.data, out[2].data);
    };
    for (double& s : result.seconds) s = 1e30;
    unsigned dropped[kNodeFormats] = {};
    for (int r = 0; r < std::max(1, repeat) + 1; ++r) {  // the first round warms up, untimed
        for (int f = 0; f < kNodeFormats; ++f) {
            check(cudaMemset(overflows.data, 0, sizeof(unsigned)));
            check(cudaEventRecord(start));
            launch(f);
            check(cudaGetLastError());
            check(cudaEventRecord(stop));
            check(cudaEventSynchronize(stop));
            float ms = 0.0f;
            check(cudaEventElapsedTime(&ms, start, stop));
            check(cudaMemcpy(&dropped[f], overflows.data, sizeof(unsigned), cudaMemcpyDeviceToHost));
            if (r > 0) result.seconds[f] = std::min(result.seconds[f], ms * 1e-3);
        }
    }
    std::vector<float> answers[kNodeFormats];
    for (int f = 0; f < kNodeFormats; ++f) {
        answers[f].resize(count);
        check(cudaMemcpy(answers[f].data(), out[f].data, count * sizeof(float), cudaMemcpyDeviceToHost));
    }
    cudaEventDestroy(start);
    cudaEventDestroy(stop);
    if (e != cudaSuccess) {
        result.why = cudaGetErrorString(e);
        return result;
    }
    result.ran = true;
    for (int f = 0; f < kNodeFormats; ++f) {
        result.stackOverflows[f] = dropped[f];
        for (uint32_t i = 0; i < count; ++i) {
            const float a = answers[f][i], b = answers[0][i];
            result.agree[f] += a == b || (std::isinf(a) && std::isinf(b));
        }
    }
    return result;
}

}  // namespace trazo
