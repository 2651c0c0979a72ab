#include "validation/operator_checks.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "kernels/corrections.hpp"
#include "neighbours/host_neighbours.hpp"
#include "scene/scene_builder.hpp"

namespace psph {

double kernel_integral(int dimension, KernelType type, int per_support) {
  const double dx = 1.0 / per_support;
  return lattice_kernel_sum(dimension, type, 1.0, dx) * std::pow(dx, dimension);
}

std::vector<double> deptulski_table_2_1_pairs() {
  // Bar L = 1 m, N = 5 cell-centred points at 50.1 ... 50.9 m, V_b = 0.2 m; "h = 2.8 dx" read as a
  // support radius of 0.56 m (cubic spline with smoothing length 1.4 dx), Deptulski
  // §2.5: his h here is not the spline's; read as the support, it reproduces Table 2.1.
  std::vector<Point<1>> pts(5);
  for (int i = 0; i < 5; ++i) pts[i][0] = Coord(50.1 + 0.2 * i);
  const Coord lo[1] = {Coord(50.0)}, hi[1] = {Coord(51.0)};
  const bool per[1] = {false};
  HostNeighbours<1> nb(pts, lo, hi, per, Coord(0.56));
  const Kernel<1> kern = Kernel<1>::make(KernelType::CubicSpline, Real(0.56));
  auto volume = [](int) { return Real(0.2); };
  auto field = [&](int k) { return 20 * double(nb.x[k][0]); };  // in double: differences of values near 1000
  int a = 0;  // stored index of point 4 (x = 50.7)
  for (int k = 0; k < 5; ++k)
    if (nb.order[k] == 3) a = k;
  const GradientCorrection<1> corr = gradient_correction(nb.view(), kern, a, volume);
  std::vector<double> pairs(4, 0.0);
  nb.view().for_each(a, [&](int b, const Vec<1>& rab, Real r) {
    const Vec<1> g = corr.gradient(kern.W(r), kern.grad(rab, r));
    const int point = nb.order[b] + 1;  // 1-based point number of the table
    if (point >= 2 && point <= 5) pairs[point - 2] = double(volume(b)) * (field(b) - field(a)) * double(g[0]);
  });
  return pairs;  // the 4-4 entry stays 0 (no self pair)
}

namespace {

template <int D>
DivergenceErrors quartic_divergence_in(int per_axis, double jitter, unsigned seed) {
  const double dx = 1.0 / per_axis;
  int n = 1;
  for (int d = 0; d < D; ++d) n *= per_axis;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-jitter * dx, jitter * dx);
  std::vector<Point<D>> pts(n);
  for (int k = 0; k < n; ++k)
    for (int d = 0, r = k; d < D; ++d, r /= per_axis) pts[k][d] = Coord(50 + (r % per_axis + 0.5) * dx + shift(rng));
  Coord lo[D], hi[D];
  bool per[D];
  for (int d = 0; d < D; ++d) lo[d] = Coord(50 - dx), hi[d] = Coord(51 + dx), per[d] = false;
  const Real support = Real(0.56);
  HostNeighbours<D> nb(pts, lo, hi, per, Coord(support));
  const Kernel<D> kern = Kernel<D>::make(KernelType::CubicSpline, support);
  const Real volume_each = Real(std::pow(dx, D));
  auto volume = [&](int) { return volume_each; };
  auto q = [](double x) { return ((-4 * x + 3) * x + 15) * x * x - x + 15; };
  auto dq = [](double x) { return ((-16 * x + 9) * x + 30) * x - 1; };
  DivergenceErrors out;
  out.points = n;
  for (int a = 0; a < n; ++a) {
    const GradientCorrection<D> corr = gradient_correction(nb.view(), kern, a, volume);
    double div = 0, exact = 0;
    for (int d = 0; d < D; ++d) exact += dq(nb.x[a][d]);
    nb.view().for_each(a, [&](int b, const Vec<D>& rab, Real r) {
      const Vec<D> g = corr.gradient(kern.W(r), kern.grad(rab, r));
      for (int d = 0; d < D; ++d) div += volume(b) * (q(nb.x[b][d]) - q(nb.x[a][d])) * g[d];
    });
    const double err = std::fabs(div - exact) / std::fabs(exact);
    out.max = std::max(out.max, err);
    if (D == 1 && nb.order[a] == 3) out.point4 = err;
  }
  return out;
}

}  // namespace

DivergenceErrors quartic_divergence(int dimension, int per_axis, double jitter, unsigned seed) {
  if (dimension == 1) return quartic_divergence_in<1>(per_axis, jitter, seed);
  if (dimension == 2) return quartic_divergence_in<2>(per_axis, jitter, seed);
  return quartic_divergence_in<3>(per_axis, jitter, seed);
}

std::vector<ValidationRecord> operator_checks() {
  std::vector<ValidationRecord> out;
  const char* names[3] = {"cubic_spline", "wendland_c2", "quintic_spline"};
  for (int d = 1; d <= 3; ++d)
    for (int t = 0; t < 3; ++t) {
      const double s = kernel_integral(d, static_cast<KernelType>(t), d == 3 ? 24 : 64);
      out.push_back(make_record("kernels", std::string(names[t]) + " integral in " + std::to_string(d) + "D", s, 1.0,
                                std::fabs(s - 1.0), 1e-3));
    }
  const std::vector<double> pairs = deptulski_table_2_1_pairs();
  const double ref[4] = {3.879, 7.572, 0.0, 8.549};
  const char* pair_names[4] = {"4-2", "4-3", "4-4", "4-5"};
  for (int k = 0; k < 4; ++k) {
    // Absolute difference: the table prints three decimals.
    out.push_back(make_record("kernels", std::string("Deptulski Table 2.1 pair ") + pair_names[k], pairs[k], ref[k],
                              std::fabs(pairs[k] - ref[k]), 1e-3));
  }
  // Deptulski §2.5 (Table 2.2, §2.5.2-2.5.4): the quartic divergence, his own error beside ours.
  const DivergenceErrors bar = quartic_divergence(1, 5);
  out.push_back(make_record("kernels", "quartic divergence, 1D, 5 points: relative error at point 4 (thesis 0.202 %)",
                            bar.point4, 0.00202, std::fabs(bar.point4 - 0.00202), 1e-4));
  out.push_back(make_record("kernels", "quartic divergence, 1D, 5 points: max relative error (thesis ~0.8 %)", bar.max,
                            0.0, bar.max, 0.009));
  for (int n : {50, 500}) {
    const double e = quartic_divergence(1, n).max;
    out.push_back(make_record("kernels", "quartic divergence, 1D, " + std::to_string(n) +
                                             " points: max relative error (thesis < 1.2 %)", e, 0.0, e, 0.012));
  }
  for (int n : {5, 50, 500}) {
    const double e = quartic_divergence(1, n, 0.25).max;
    out.push_back(make_record("kernels", "quartic divergence, 1D, " + std::to_string(n) +
                                             " points jittered by 0.25 spacing: max relative error (thesis ~1 %)",
                              e, 0.0, e, 0.02));
  }
  for (int d : {2, 3}) {
    const double e = quartic_divergence(d, 5).max;
    out.push_back(make_record("kernels", "quartic divergence, " + std::to_string(d) +
                                             "D, 5 points per axis: max relative error (thesis ~1 %)", e, 0.0, e, 0.01));
  }
  return out;
}

}  // namespace psph
