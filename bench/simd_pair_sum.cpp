// How much explicit SIMD over a particle's neighbours gives a pair loop on a CPU (BENCHMARKS.md,
// "Mixed precision against double on the CPU"): the continuity sum drho_i = sum_j m_j (v_i - v_j)
// . d_ij F(r_ij) (Pazdniakou 2018 eq. 53a; cubic spline, Deptulski 2021 eq. 2.11) over a row-major
// neighbour list of a 3D jittered lattice (support 2 spacings, the list's radius 1.1 supports, as
// the engine's skin), positions in double as in mixed precision: scalar as the engine's pair loops
// are, and with std::experimental::simd (GCC 12) lanes over the neighbours, in double and float.
// A measurement, not the engine's code:
//   g++ -O3 -fopenmp -std=gnu++17 bench/simd_pair_sum.cpp -o /tmp/simd_pair_sum   (add -march=native
//   for the host's widest vectors); OMP_NUM_THREADS=2 /tmp/simd_pair_sum
#include <experimental/simd>
#include <omp.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>
namespace stdx = std::experimental;

constexpr int n1 = 48, cap = 64;
constexpr double R = 2.0, h = 1.0, skin = 1.1;
std::vector<double> X;  // 3 per particle
std::vector<int> idx, cnt;
int N;

void build() {
  N = n1 * n1 * n1;
  std::mt19937 g(1);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  X.resize(3 * N);
  for (int i = 0; i < N; ++i) {
    int a = i % n1, b = (i / n1) % n1, c = i / (n1 * n1);
    X[3 * i] = a + u(g), X[3 * i + 1] = b + u(g), X[3 * i + 2] = c + u(g);
  }
  idx.assign(size_t(N) * cap, 0), cnt.assign(N, 0);
  const double L = skin * R;
  for (int i = 0; i < N; ++i) {
    int a = i % n1, b = (i / n1) % n1, c = i / (n1 * n1);
    for (int dc = -3; dc <= 3; ++dc) for (int db = -3; db <= 3; ++db) for (int da = -3; da <= 3; ++da) {
      int A = a + da, B = b + db, C = c + dc;
      if (A < 0 || B < 0 || C < 0 || A >= n1 || B >= n1 || C >= n1) continue;
      int j = A + n1 * (B + n1 * C);
      if (j == i) continue;
      double dx = X[3*i]-X[3*j], dy = X[3*i+1]-X[3*j+1], dz = X[3*i+2]-X[3*j+2];
      if (dx*dx+dy*dy+dz*dz < L*L) idx[size_t(i)*cap + cnt[i]++] = j;
    }
  }
}

template <class T> T Fq(T q) {  // (dw/dq)/q, cubic spline
  return q < T(1) ? T(-3) + T(2.25) * q : T(-0.75) * (T(2) - q) * (T(2) - q) / q;
}

template <class T>
double scalar(const std::vector<T>& v, const std::vector<T>& m, std::vector<T>& out) {
  const T R2 = T(R * R), ih = T(1 / h), norm = T(1 / M_PI);
  auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static)
  for (int i = 0; i < N; ++i) {
    T acc = 0;
    const double xi0 = X[3*i], xi1 = X[3*i+1], xi2 = X[3*i+2];
    const T vi0 = v[3*i], vi1 = v[3*i+1], vi2 = v[3*i+2];
    const int* row = &idx[size_t(i) * cap];
    for (int k = 0; k < cnt[i]; ++k) {
      const int j = row[k];
      const T d0 = T(xi0 - X[3*j]), d1 = T(xi1 - X[3*j+1]), d2 = T(xi2 - X[3*j+2]);
      const T r2 = d0*d0 + d1*d1 + d2*d2;
      if (r2 < R2) {
        const T q = std::sqrt(r2) * ih;
        acc += m[j] * ((vi0 - v[3*j]) * d0 + (vi1 - v[3*j+1]) * d1 + (vi2 - v[3*j+2]) * d2) * Fq(q);
      }
    }
    out[i] = acc * norm;
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

template <class T>
double simd(const std::vector<T>& v, const std::vector<T>& m, std::vector<T>& out) {
  using S = stdx::native_simd<T>;
  constexpr int W = S::size();
  const T R2 = T(R * R), ih = T(1 / h), norm = T(1 / M_PI);
  auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static)
  for (int i = 0; i < N; ++i) {
    S acc = 0;
    const double xi0 = X[3*i], xi1 = X[3*i+1], xi2 = X[3*i+2];
    const T vi0 = v[3*i], vi1 = v[3*i+1], vi2 = v[3*i+2];
    const int* row = &idx[size_t(i) * cap];
    const int c = cnt[i];
    for (int k = 0; k < c; k += W) {
      int jj[W];
      for (int l = 0; l < W; ++l) jj[l] = k + l < c ? row[k + l] : i;  // the tail reads i itself: r = 0, masked
      const S d0([&](auto l) { return T(xi0 - X[3*jj[l]]); });
      const S d1([&](auto l) { return T(xi1 - X[3*jj[l]+1]); });
      const S d2([&](auto l) { return T(xi2 - X[3*jj[l]+2]); });
      const S r2 = d0*d0 + d1*d1 + d2*d2;
      const auto in = r2 < R2 && r2 > T(0);
      if (stdx::none_of(in)) continue;
      const S q = stdx::sqrt(r2) * ih;
      S f = T(-3) + T(2.25) * q;
      const S t = T(2) - q;
      stdx::where(q >= T(1), f) = T(-0.75) * t * t / q;
      const S dv = (vi0 - S([&](auto l) { return v[3*jj[l]]; })) * d0 + (vi1 - S([&](auto l) { return v[3*jj[l]+1]; })) * d1 +
                   (vi2 - S([&](auto l) { return v[3*jj[l]+2]; })) * d2;
      const S mj([&](auto l) { return m[jj[l]]; });
      stdx::where(in, acc) += mj * dv * f;
    }
    out[i] = stdx::reduce(acc) * norm;
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

template <class T>
void run(const char* name) {
  std::vector<T> v(3 * N), m(N, T(1)), a(N), b(N);
  for (int i = 0; i < 3 * N; ++i) v[i] = T(std::sin(0.37 * i));
  double ts = 1e9, tv = 1e9;
  for (int r = 0; r < 7; ++r) ts = std::min(ts, scalar(v, m, a)), tv = std::min(tv, simd(v, m, b));
  double err = 0, big = 0;
  for (int i = 0; i < N; ++i) err = std::max(err, double(std::fabs(a[i] - b[i]))), big = std::max(big, double(std::fabs(a[i])));
  long pairs = 0;
  for (int i = 0; i < N; ++i) pairs += cnt[i];
  std::printf("%s: lanes %d, scalar %.4f s, simd %.4f s (%.2fx), %.2f ns per listed pair scalar; max diff %.2e of %.2e\n", name,
              int(stdx::native_simd<T>::size()), ts, tv, ts / tv, 1e9 * ts * omp_get_max_threads() / pairs, err, big);
}

int main() {
  build();
  long pairs = 0;
  for (int i = 0; i < N; ++i) pairs += cnt[i];
  std::printf("%d particles, %.1f listed neighbours each, %d threads\n", N, double(pairs) / N, omp_get_max_threads());
  run<double>("double");
  run<float>("float ");
}
