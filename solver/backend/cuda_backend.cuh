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
#include <vector>

#include "core/pass_profile.hpp"

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

// Times one launch with a pair of events into the focused profile, if any: read when the profile
// resolves them (core/pass_profile.hpp), so that the launch is not waited for.
// Event pairs for the pass clock, created once and reused: the resolver hands each pair back
// after reading it (creating and destroying two events per launch costs more than many launches).
// The profile is recorded and resolved on the thread that launches.
class EventPairs {
 public:
  static cudaEvent_t* take() {
    std::vector<cudaEvent_t*>& f = free_pairs();
    if (!f.empty()) {
      cudaEvent_t* e = f.back();
      f.pop_back();
      return e;
    }
    cudaEvent_t* e = new cudaEvent_t[2];
    PSPH_CUDA(cudaEventCreate(&e[0]));
    PSPH_CUDA(cudaEventCreate(&e[1]));
    return e;
  }
  static void give(cudaEvent_t* e) { free_pairs().push_back(e); }

 private:
  static std::vector<cudaEvent_t*>& free_pairs() {
    static std::vector<cudaEvent_t*> f;
    return f;
  }
};

class DevicePassClock {
 public:
  explicit DevicePassClock(const std::string& pass) : focus_(profile_focus()), pass_(pass) {
    if (!focus_.profile) return;
    events_ = EventPairs::take();
    PSPH_CUDA(cudaEventRecord(events_[0]));
  }
  ~DevicePassClock() {
    if (!focus_.profile) return;
    cudaEventRecord(events_[1]);  // no throw from destructors
    focus_.profile->defer(focus_.stage, &pass_, events_, &seconds_between);
  }
  DevicePassClock(const DevicePassClock&) = delete;
  DevicePassClock& operator=(const DevicePassClock&) = delete;

 private:
  static double seconds_between(void* handle) {
    cudaEvent_t* e = static_cast<cudaEvent_t*>(handle);
    float ms = 0;
    if (cudaEventSynchronize(e[1]) != cudaSuccess || cudaEventElapsedTime(&ms, e[0], e[1]) != cudaSuccess) ms = 0;
    EventPairs::give(e);
    return 1e-3 * ms;
  }
  ProfileFocus focus_;
  const std::string& pass_;
  cudaEvent_t* events_ = nullptr;
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
    const DevicePassClock clock(pass_name_of<F>());
    for_each_kernel<<<(n + block - 1) / block, block>>>(n, f);
    PSPH_CUDA(cudaGetLastError());
  }
  template <class T, class F>
  static T max_of(int n, const F& f) {
    const DevicePassClock clock(pass_name_of<F>());
    return thrust::transform_reduce(thrust::device, thrust::counting_iterator<int>(0),
                                    thrust::counting_iterator<int>(n), ApplyIndex<T, F>{f},
                                    std::numeric_limits<T>::lowest(), thrust::maximum<T>());
  }
  template <class T, class F>
  static T sum_of(int n, const F& f) {
    const DevicePassClock clock(pass_name_of<F>());
    return thrust::transform_reduce(thrust::device, thrust::counting_iterator<int>(0),
                                    thrust::counting_iterator<int>(n), ApplyIndex<T, F>{f}, T{},
                                    thrust::plus<T>());
  }

  // Stable sort by cell key (keys are overwritten with the sorted keys); perm[new] = old.
  static void sort_by_cell(int* keys, int n, int ncells, int* perm, int* cell_start, int* cell_end) {
    static const std::string name = "sort_by_cell";
    const DevicePassClock clock(name);
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
