#include "validation/operator_checks.hpp"

#include <cmath>
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
  // support radius of 0.56 m (cubic spline with smoothing length 1.4 dx), digest §4.2.
  std::vector<Vec<1>> pts(5);
  for (int i = 0; i < 5; ++i) pts[i][0] = Real(50.1 + 0.2 * i);
  const Real lo[1] = {Real(50.0)}, hi[1] = {Real(51.0)};
  const bool per[1] = {false};
  HostNeighbours<1> nb(pts, lo, hi, per, Real(0.56));
  const Kernel<1> kern = Kernel<1>::make(KernelType::CubicSpline, Real(0.56));
  auto volume = [](int) { return Real(0.2); };
  auto field = [&](int k) { return Real(20) * nb.x[k][0]; };
  int a = 0;  // stored index of point 4 (x = 50.7)
  for (int k = 0; k < 5; ++k)
    if (nb.order[k] == 3) a = k;
  const GradientCorrection<1> corr = gradient_correction(nb.view(), kern, a, volume);
  std::vector<double> pairs(4, 0.0);
  nb.view().for_each(a, [&](int b, const Vec<1>& rab, Real r) {
    const Vec<1> g = corr.gradient(kern.W(r), kern.grad(rab, r));
    const int point = nb.order[b] + 1;  // 1-based point number of the table
    if (point >= 2 && point <= 5) pairs[point - 2] = double(volume(b) * (field(b) - field(a)) * g[0]);
  });
  return pairs;  // the 4-4 entry stays 0 (no self pair)
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
  return out;
}

}  // namespace psph
