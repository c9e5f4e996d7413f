// The one place that knows whether code is compiled for the GPU.
// Every per-element function that both backends run is marked SHEAF_HD and lives in a header.
#pragma once

#if defined(__CUDACC__)
#define SHEAF_HD __host__ __device__
#define SHEAF_HD_INLINE __host__ __device__ __forceinline__
#else
#define SHEAF_HD
#define SHEAF_HD_INLINE inline
#endif
