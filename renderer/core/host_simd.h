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

// TRAZO_HOST_AVX: host code compiled for AVX2 (the CPU backend's AVX2 and AVX-512 kernels): meshes are then
// traversed over eight-wide nodes (accel/wide8_traverse.h).
#if TRAZO_HOST_SSE && defined(__AVX2__)
#include <immintrin.h>
#define TRAZO_HOST_AVX 1
#else
#define TRAZO_HOST_AVX 0
#endif
