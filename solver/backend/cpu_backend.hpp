#pragma once
// OpenMP backend: memory, launching, sorting and reductions on the host, each launch timed into the
// focused profile (core/pass_profile.hpp). Physics never lives here.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <string>
#include <vector>

#include "core/exact_sum.hpp"
#include "core/pass_profile.hpp"

#if defined(_OPENMP)
#include <omp.h>
#endif

namespace psph {

struct CpuBackend {
  static constexpr const char* name = "cpu";
  static constexpr bool list_rows_contiguous = true;  // neighbour lists row-major (cache lines per particle)
  static constexpr bool host_memory = true;           // its arrays are the host's: read in place

  static void* allocate(std::size_t bytes) {
    if (bytes == 0) return nullptr;
    void* p = std::aligned_alloc(64, (bytes + 63) / 64 * 64);
    if (!p) throw std::bad_alloc();
    return p;
  }
  static void release(void* p) { std::free(p); }
  static void upload(void* dst, const void* src, std::size_t bytes) { if (bytes) std::memcpy(dst, src, bytes); }
  static void download(void* dst, const void* src, std::size_t bytes) { if (bytes) std::memcpy(dst, src, bytes); }
  static void copy(void* dst, const void* src, std::size_t bytes) { if (bytes) std::memcpy(dst, src, bytes); }
  static void fill_zero(void* dst, std::size_t bytes) { if (bytes) std::memset(dst, 0, bytes); }
  static void synchronize() {}

  static int thread_index() {
#if defined(_OPENMP)
    return omp_get_thread_num();
#else
    return 0;
#endif
  }
  static int threads() {
#if defined(_OPENMP)
    return omp_get_max_threads();
#else
    return 1;
#endif
  }
  // The processor's model name from /proc/cpuinfo, with the thread count.
  static std::string device_name() {
    std::string model = "unknown CPU";
    if (FILE* f = std::fopen("/proc/cpuinfo", "r")) {
      char line[512];
      while (std::fgets(line, sizeof line, f))
        if (std::strncmp(line, "model name", 10) == 0) {
          const char* c = std::strchr(line, ':');
          if (c) model = std::string(c + 2, std::strcspn(c + 2, "\n"));
          break;
        }
      std::fclose(f);
    }
    return model + " (" + std::to_string(threads()) + " threads)";
  }

  template <class F>
  static void for_each(int n, const F& f) {
    const HostPassClock clock(pass_name_of<F>());
#pragma omp parallel for schedule(dynamic, 256)
    for (int i = 0; i < n; ++i) f(i);
  }

  // max over i of f(i); -inf for n = 0.
  template <class T, class F>
  static T max_of(int n, const F& f) {
    const HostPassClock clock(pass_name_of<F>());
    T m = std::numeric_limits<T>::lowest();
#pragma omp parallel for schedule(static) reduction(max : m)
    for (int i = 0; i < n; ++i) m = std::max(m, f(i));
    return m;
  }
  // Adds f(i) for every i into acc (one exact accumulator per Real component of T:
  // core/exact_sum.hpp), so that the sum depends neither on the thread count nor on the order.
  template <class T, class F>
  static void accumulate(int n, const F& f, ExactSum* acc) {
    const HostPassClock clock(pass_name_of<F>());
    using C = RealComponents<T>;
    std::vector<ExactSum> part(static_cast<std::size_t>(threads()) * C::count);
#pragma omp parallel
    {
      ExactSum* mine = part.data() + static_cast<std::size_t>(thread_index()) * C::count;
#pragma omp for schedule(static)
      for (int i = 0; i < n; ++i) {
        const T v = f(i);
        for (int k = 0; k < C::count; ++k) mine[k].add(double(C::get(v, k)));
      }
    }
    for (std::size_t t = 0; t < part.size(); ++t) acc[t % C::count].merge(part[t]);
  }
  template <class T, class F>
  static T sum_of(int n, const F& f) {
    return exact_sum_of<T, CpuBackend>(n, f);
  }

  // Counting sort of particles by cell key, ties by id (when ids are given): perm[new] = old; cells
  // get [start, end). With ids the order within a cell is a function of the particles alone, not
  // of their order before the sort (nor of which process holds them).
  static void sort_by_cell(int* keys, int n, int ncells, int* perm, int* cell_start, int* cell_end,
                           const std::int32_t* ids = nullptr) {
    static const std::string name = "sort_by_cell";
    const HostPassClock clock(name);
    std::fill(cell_end, cell_end + ncells, 0);
    for (int i = 0; i < n; ++i) ++cell_end[keys[i]];
    int acc = 0;
    for (int c = 0; c < ncells; ++c) {
      cell_start[c] = acc;
      acc += cell_end[c];
      cell_end[c] = cell_start[c];
    }
    for (int i = 0; i < n; ++i) perm[cell_end[keys[i]]++] = i;
    if (!ids) return;
#pragma omp parallel for schedule(dynamic, 1024)
    for (int c = 0; c < ncells; ++c)  // cells hold a few particles: insertion sort
      for (int a = cell_start[c] + 1; a < cell_end[c]; ++a) {
        const int p = perm[a];
        int b = a;
        for (; b > cell_start[c] && ids[perm[b - 1]] > ids[p]; --b) perm[b] = perm[b - 1];
        perm[b] = p;
      }
  }
};

}  // namespace psph
