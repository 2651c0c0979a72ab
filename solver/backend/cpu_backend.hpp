#pragma once
// OpenMP backend: memory, launching, sorting and reductions on the host, each launch timed into the
// focused profile (core/pass_profile.hpp). Physics never lives here.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <string>
#include <vector>

#include "core/pass_profile.hpp"

#if defined(_OPENMP)
#include <omp.h>
#endif

namespace psph {

struct CpuBackend {
  static constexpr const char* name = "cpu";
  static constexpr bool list_rows_contiguous = true;  // neighbour lists row-major (cache lines per particle)

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
  template <class T, class F>
  static T sum_of(int n, const F& f) {
    // Fixed-order blocked sum, so the result does not depend on the thread count.
    const HostPassClock clock(pass_name_of<F>());
    constexpr int block = 4096;
    const int nb = (n + block - 1) / block;
    std::vector<T> part(static_cast<std::size_t>(nb), T{});
#pragma omp parallel for schedule(static)
    for (int b = 0; b < nb; ++b) {
      T s = T{};
      const int end = std::min(n, (b + 1) * block);
      for (int i = b * block; i < end; ++i) s += f(i);
      part[static_cast<std::size_t>(b)] = s;
    }
    T s = T{};
    for (T v : part) s += v;
    return s;
  }

  // Stable counting sort of particles by cell key: perm[new] = old; cells get [start, end).
  static void sort_by_cell(int* keys, int n, int ncells, int* perm, int* cell_start, int* cell_end) {
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
  }
};

}  // namespace psph
