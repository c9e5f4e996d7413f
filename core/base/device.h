// The one place that knows whether code is compiled for the GPU.
// Every per-element function that both backends run is marked SHEAF_HD and lives in a header.
#pragma once

#if defined(__CUDACC__)
#define SHEAF_HD __host__ __device__
#define SHEAF_HD_INLINE __host__ __device__ __forceinline__
// A large function kept out of its callers: recursive device code (CSG) then holds its stack
// once, at the leaf, instead of once per level of recursion, and code reached from many call
// sites and kernels (the pattern dispatch, normal perturbation) is compiled once, not once per
// site: inlined everywhere, those made ptxas need 14 GiB for the module and fail CI's build.
#define SHEAF_HD_NOINLINE __host__ __device__ __noinline__
// The bodies of the wavefront pipeline's launches: extended lambdas (nvcc --extended-lambda).
#define SHEAF_HD_LAMBDA __host__ __device__
// A small function in the innermost loops (the exact ray-triangle test), inlined where the
// compiler's own weighing would call it.
#define SHEAF_HD_HOT __host__ __device__ __forceinline__
#else
#define SHEAF_HD
#define SHEAF_HD_INLINE inline
#define SHEAF_HD_NOINLINE inline
#define SHEAF_HD_LAMBDA
#define SHEAF_HD_HOT inline __attribute__((always_inline))
#endif

// 1 while nvcc compiles device code, 0 for host code (g++, or nvcc's host pass): the few
// host-only branches of shared code (image textures through OpenImageIO, std::atomic_ref)
// test this and nothing else.
#if defined(__CUDA_ARCH__)
#define SHEAF_DEVICE_PASS 1
#else
#define SHEAF_DEVICE_PASS 0
#endif
