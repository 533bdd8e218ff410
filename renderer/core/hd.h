// The one macro that makes a function callable from host code and from CUDA kernels.
#pragma once

#if defined(__CUDACC__)
#define TRAZO_HD __host__ __device__ __forceinline__
#define TRAZO_HD_CALL __host__ __device__ __noinline__
#else
#define TRAZO_HD inline
#define TRAZO_HD_CALL inline
#endif
