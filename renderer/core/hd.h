// The one macro that makes a function callable from host code and from CUDA kernels.
#pragma once

#if defined(__CUDACC__)
#define TRAZO_HD __host__ __device__ __forceinline__
#define TRAZO_DEVICE_COMPILE 1
#else
#define TRAZO_HD inline
#define TRAZO_DEVICE_COMPILE 0
#endif
