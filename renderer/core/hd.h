// The one macro that makes a function callable from host code and from CUDA kernels.
#pragma once

// TRAZO_HD_CALL: a function the device calls rather than inlines, where a large, rarely taken body (a CSG
// solid) would otherwise crowd every call site's registers. Still `inline` for the linker: headers define it.
// TRAZO_HD_HOST_CALL: inlined on the device, called on the host, where GCC would otherwise inline a mesh's own
// shadow traversal into the top level's loop and crowd its registers (13% more instructions a shadow ray).
// TRAZO_HD_HOT: inlined on the host too, for a small per-ray or per-node step that GCC would otherwise call out
// of line from a large caller (the renderer's mesh traversal inside the top level's).
// TRAZO_HD_DEVICE_CALL: called on the device, where inlining it at every call site would hold a kernel's registers
// (an object kind's hit point), and inlined on the host, where GCC would otherwise call it out of line.
#if defined(__CUDACC__)
#define TRAZO_HD __host__ __device__ __forceinline__
#define TRAZO_HD_CALL __host__ __device__ __noinline__ inline
#define TRAZO_HD_HOST_CALL __host__ __device__ __forceinline__
#define TRAZO_HD_HOT __host__ __device__ __forceinline__
#define TRAZO_HD_DEVICE_CALL __host__ __device__ __noinline__ inline
#else
#define TRAZO_HD inline
#define TRAZO_HD_CALL inline
#define TRAZO_HD_HOST_CALL __attribute__((noinline)) inline
#define TRAZO_HD_HOT inline __attribute__((always_inline))
#define TRAZO_HD_DEVICE_CALL inline __attribute__((always_inline))
#endif

// Marks a point control never reaches (after a switch that returns for every enumerator).
#define TRAZO_UNREACHABLE() __builtin_unreachable()

// 1 where kernel code takes the device's paths (lane loops instead of SSE, run-time triangle axes, the device's
// stack sizes, branch-free BRDFs): in CUDA device compilation, and in a host build with
// TRAZO_EMULATE_DEVICE_PATHS, which runs those paths on the CPU so CI tests them (trazo_device_paths). Only
// what needs CUDA itself (intrinsics) stays behind __CUDA_ARCH__.
#if defined(__CUDA_ARCH__) || defined(TRAZO_EMULATE_DEVICE_PATHS)
#define TRAZO_DEVICE_PATHS 1
#else
#define TRAZO_DEVICE_PATHS 0
#endif
