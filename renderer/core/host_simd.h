// TRAZO_HOST_SSE: whether kernel code takes its SSE2 forms (host code on x86-64) rather than the lane loops
// the device runs (core/hd.h, TRAZO_DEVICE_PATHS). Both forms do the same IEEE operations in the same order.
#pragma once

#include "core/hd.h"

#if !TRAZO_DEVICE_PATHS && defined(__SSE2__)
#include <emmintrin.h>
#define TRAZO_HOST_SSE 1
#else
#define TRAZO_HOST_SSE 0
#endif

// TRAZO_HOST_PACKETS: host code that g++ compiles for x86-64 (not the device, nor nvcc's host pass, which renders
// nothing): the CPU's packet engine (integrator/packets/) and the thesis's shading of packets' hits.
#if TRAZO_HOST_SSE && !defined(__CUDACC__)
#define TRAZO_HOST_PACKETS 1
#else
#define TRAZO_HOST_PACKETS 0
#endif

// TRAZO_HOST_AVX: host code compiled for AVX2 (the CPU backend's AVX2 and AVX-512 kernels): meshes are then
// traversed over eight-wide nodes (accel/wide8_traverse.h).
#if TRAZO_HOST_SSE && defined(__AVX2__)
#include <immintrin.h>
#define TRAZO_HOST_AVX 1
#else
#define TRAZO_HOST_AVX 0
#endif

// TRAZO_HOST_AVX512: host code compiled for AVX-512 (the CPU backend's AVX-512 kernels): a mesh leaf's run of three
// or four blocks is then tested in one sixteen-lane test (geometry/intersect_triangle_leaf.h).
#if TRAZO_HOST_AVX && defined(__AVX512F__)
#define TRAZO_HOST_AVX512 1
#else
#define TRAZO_HOST_AVX512 0
#endif
