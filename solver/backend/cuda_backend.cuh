#pragma once
// CUDA backend: explicit device memory (cudaMalloc), kernel launches, CCCL sort and reductions.
// Only .cu translation units include this header. Physics never lives here.
#include <cuda_runtime.h>
#include <thrust/device_ptr.h>
#include <thrust/execution_policy.h>
#include <thrust/functional.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/sequence.h>
#include <thrust/sort.h>
#include <thrust/transform_reduce.h>

#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace psph {

inline void cuda_check(cudaError_t e, const char* what, const char* file, int line) {
  if (e != cudaSuccess)
    throw std::runtime_error(std::string("CUDA error in ") + what + " (" + file + ":" + std::to_string(line) +
                             "): " + cudaGetErrorString(e));
}
#define PSPH_CUDA(call) ::psph::cuda_check((call), #call, __FILE__, __LINE__)

template <class F>
__global__ void for_each_kernel(int n, F f) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n) f(i);
}

__global__ inline void cell_ranges_kernel(const int* keys, int n, int* start, int* end) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  const int k = keys[i];
  if (i == 0 || keys[i - 1] != k) start[k] = i;
  if (i == n - 1 || keys[i + 1] != k) end[k] = i + 1;
}

template <class T, class F>
struct ApplyIndex {
  F f;
  __host__ __device__ T operator()(int i) const { return f(i); }
};

struct CudaBackend {
  static constexpr const char* name = "cuda";
  static constexpr int block = 256;
  static constexpr bool list_rows_contiguous = false;  // column-major lists: coalesced across a warp

  static void* allocate(std::size_t bytes) {
    if (bytes == 0) return nullptr;
    void* p = nullptr;
    PSPH_CUDA(cudaMalloc(&p, bytes));
    return p;
  }
  static void release(void* p) {
    if (p) cudaFree(p);  // no throw from destructors
  }
  static void upload(void* dst, const void* src, std::size_t bytes) {
    if (bytes) PSPH_CUDA(cudaMemcpy(dst, src, bytes, cudaMemcpyHostToDevice));
  }
  static void download(void* dst, const void* src, std::size_t bytes) {
    if (bytes) PSPH_CUDA(cudaMemcpy(dst, src, bytes, cudaMemcpyDeviceToHost));
  }
  static void copy(void* dst, const void* src, std::size_t bytes) {
    if (bytes) PSPH_CUDA(cudaMemcpy(dst, src, bytes, cudaMemcpyDeviceToDevice));
  }
  static void fill_zero(void* dst, std::size_t bytes) {
    if (bytes) PSPH_CUDA(cudaMemset(dst, 0, bytes));
  }
  static void synchronize() { PSPH_CUDA(cudaDeviceSynchronize()); }
  static int threads() { return 1; }
  static std::string device_name() {
    int dev = 0;
    PSPH_CUDA(cudaGetDevice(&dev));
    cudaDeviceProp prop{};
    PSPH_CUDA(cudaGetDeviceProperties(&prop, dev));
    return prop.name;
  }

  template <class F>
  static void for_each(int n, const F& f) {
    if (n <= 0) return;
    for_each_kernel<<<(n + block - 1) / block, block>>>(n, f);
    PSPH_CUDA(cudaGetLastError());
  }
  template <class T, class F>
  static T max_of(int n, const F& f) {
    return thrust::transform_reduce(thrust::device, thrust::counting_iterator<int>(0),
                                    thrust::counting_iterator<int>(n), ApplyIndex<T, F>{f},
                                    std::numeric_limits<T>::lowest(), thrust::maximum<T>());
  }
  template <class T, class F>
  static T sum_of(int n, const F& f) {
    return thrust::transform_reduce(thrust::device, thrust::counting_iterator<int>(0),
                                    thrust::counting_iterator<int>(n), ApplyIndex<T, F>{f}, T{},
                                    thrust::plus<T>());
  }

  // Stable sort by cell key (keys are overwritten with the sorted keys); perm[new] = old.
  static void sort_by_cell(int* keys, int n, int ncells, int* perm, int* cell_start, int* cell_end) {
    fill_zero(cell_start, sizeof(int) * ncells);
    fill_zero(cell_end, sizeof(int) * ncells);
    if (n == 0) return;
    thrust::device_ptr<int> k(keys), p(perm);
    thrust::sequence(thrust::device, p, p + n);
    thrust::stable_sort_by_key(thrust::device, k, k + n, p);
    cell_ranges_kernel<<<(n + block - 1) / block, block>>>(keys, n, cell_start, cell_end);
    PSPH_CUDA(cudaGetLastError());
  }
};

}  // namespace psph
