#pragma once
// CUDA backend: explicit device memory (cudaMalloc), kernel launches, CCCL sort and reductions.
// Only .cu translation units include this header. Physics never lives here.
#include <cuda_runtime.h>
#include <cub/block/block_reduce.cuh>
#include <thrust/device_ptr.h>
#include <thrust/execution_policy.h>
#include <thrust/functional.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/sequence.h>
#include <thrust/sort.h>
#include <thrust/transform_reduce.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/exact_sum.hpp"
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

// The sort key: cell key in the high word, the tie-breaking id in the low one.
__global__ inline void key_id_kernel(const int* keys, const std::int32_t* ids, int n, unsigned long long* out) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n) out[i] = static_cast<unsigned long long>(keys[i]) << 32 | static_cast<std::uint32_t>(ids ? ids[i] : i);
}
__global__ inline void cell_of_key_kernel(const unsigned long long* key_id, int n, int* keys) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n) keys[i] = static_cast<int>(key_id[i] >> 32);
}

struct BitOr {
  __device__ long long operator()(long long a, long long b) const { return a | b; }
};

// Exact sums (core/exact_sum.hpp): each thread accumulates a strided share, each block adds its
// threads' digits (integers: exact) into one accumulator per component, written to `out`.
template <class T, class F, int Threads>
__global__ void accumulate_kernel(int n, F f, std::int64_t* out_words, int* out_special) {
  using C = RealComponents<T>;
  ExactSum acc[C::count];
  for (int i = blockIdx.x * Threads + threadIdx.x; i < n; i += gridDim.x * Threads) {
    const T v = f(i);
    for (int k = 0; k < C::count; ++k) acc[k].add(double(C::get(v, k)));
  }
  using Words = cub::BlockReduce<long long, Threads>;
  __shared__ typename Words::TempStorage tmp;
  for (int k = 0; k < C::count; ++k) {
    acc[k].carry();
    for (int w = 0; w < ExactSum::kDigits; ++w) {
      const long long sum = Words(tmp).Sum(static_cast<long long>(acc[k].words()[w]));
      __syncthreads();
      if (threadIdx.x == 0) out_words[(blockIdx.x * C::count + k) * ExactSum::kDigits + w] = sum;
    }
    const long long special = Words(tmp).Reduce(static_cast<long long>(acc[k].special()), BitOr{});
    __syncthreads();
    if (threadIdx.x == 0) out_special[blockIdx.x * C::count + k] = static_cast<int>(special);
  }
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
  static constexpr bool host_memory = false;           // halos go through host copies

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
  // Device memory for the backend's own launches (reductions, the sort's keys), slot by slot: grown
  // as needed and kept, so that a reduction allocates nothing.
  enum Scratch { kSumWords, kSumSpecial, kSortKeys, kScratchSlots };
  static void* scratch(Scratch slot, std::size_t bytes) {
    static void* block[kScratchSlots] = {};
    static std::size_t capacity[kScratchSlots] = {};
    if (bytes > capacity[slot]) {
      release(block[slot]);
      block[slot] = nullptr, capacity[slot] = 0;
      block[slot] = allocate(bytes);
      capacity[slot] = bytes;
    }
    return block[slot];
  }
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
  // Adds f(i) for every i into acc, one exact accumulator per Real component of T.
  template <class T, class F>
  static void accumulate(int n, const F& f, ExactSum* acc) {
    if (n <= 0) return;
    const DevicePassClock clock(pass_name_of<F>());
    constexpr int threads = 128, count = RealComponents<T>::count;
    const int blocks = std::min(256, (n + threads - 1) / threads);
    const std::size_t words = std::size_t(blocks) * count * ExactSum::kDigits;
    auto* d_words = static_cast<std::int64_t*>(scratch(kSumWords, words * sizeof(std::int64_t)));
    auto* d_special = static_cast<int*>(scratch(kSumSpecial, std::size_t(blocks) * count * sizeof(int)));
    accumulate_kernel<T, F, threads><<<blocks, threads>>>(n, f, d_words, d_special);
    PSPH_CUDA(cudaGetLastError());
    std::vector<std::int64_t> h_words(words);
    std::vector<int> h_special(std::size_t(blocks) * count);
    download(h_words.data(), d_words, words * sizeof(std::int64_t));
    download(h_special.data(), d_special, h_special.size() * sizeof(int));
    for (int b = 0; b < blocks; ++b)
      for (int k = 0; k < count; ++k) {
        ExactSum part;
        const std::size_t at = (std::size_t(b) * count + k) * ExactSum::kDigits;
        for (int w = 0; w < ExactSum::kDigits; ++w) part.words()[w] = h_words[at + w];
        part.special() = h_special[std::size_t(b) * count + k];
        acc[k].merge(part);
      }
  }
  template <class T, class F>
  static T sum_of(int n, const F& f) {
    return exact_sum_of<T, CudaBackend>(n, f);
  }

  // Sort by cell key, ties by id (by index without ids); keys are overwritten with the sorted
  // keys; perm[new] = old.
  static void sort_by_cell(int* keys, int n, int ncells, int* perm, int* cell_start, int* cell_end,
                           const std::int32_t* ids = nullptr) {
    static const std::string name = "sort_by_cell";
    const DevicePassClock clock(name);
    fill_zero(cell_start, sizeof(int) * ncells);
    fill_zero(cell_end, sizeof(int) * ncells);
    if (n == 0) return;
    const int grid = (n + block - 1) / block;
    auto* key_id = static_cast<unsigned long long*>(scratch(kSortKeys, sizeof(unsigned long long) * n));
    key_id_kernel<<<grid, block>>>(keys, ids, n, key_id);
    thrust::device_ptr<unsigned long long> k(key_id);
    thrust::device_ptr<int> p(perm);
    thrust::sequence(thrust::device, p, p + n);
    thrust::sort_by_key(thrust::device, k, k + n, p);
    cell_of_key_kernel<<<grid, block>>>(key_id, n, keys);
    cell_ranges_kernel<<<grid, block>>>(keys, n, cell_start, cell_end);
    PSPH_CUDA(cudaGetLastError());
  }
};

}  // namespace psph
