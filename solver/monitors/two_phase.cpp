#include "monitors/two_phase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "monitors/particle_volumes.hpp"
#include "state/derived_fields.hpp"

namespace psph {
namespace {

bool inside(const MonitorRegion& r, const double* x, int D) {
  for (int k = 0; k < D; ++k)
    if (x[k] < r.lower[k] || x[k] > r.upper[k]) return false;
  return true;
}

// Union-find with path halving.
int root(std::vector<int>& parent, int a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

}  // namespace

bool gas_percolates(const Scene& sc, const MonitorRegion& region, const std::vector<double>& x,
                    const std::vector<int>& gas) {
  const int D = sc.dimension, n = static_cast<int>(gas.size());
  const double rc = region.percolation_distance;
  if (n == 0 || !(rc > 0)) return false;
  // Cells of edge >= rc over the region; along periodic axes (not the flow axis) the cells wrap,
  // which needs the region to span the domain on that axis.
  std::array<long, 3> cells{1, 1, 1};
  std::array<bool, 3> wrap{false, false, false};
  std::array<double, 3> edge{1, 1, 1};
  for (int k = 0; k < D; ++k) {
    const double L = region.upper[k] - region.lower[k];
    wrap[k] = sc.periodic[k] && k != region.flow_axis && L >= sc.upper[k] - sc.lower[k] - 1e-12;
    cells[k] = std::max(1L, static_cast<long>(std::floor(L / rc)));
    edge[k] = L / cells[k];
  }
  auto cell_of = [&](int i, int k) {
    const long c = static_cast<long>(std::floor((x[gas[i] * D + k] - region.lower[k]) / edge[k]));
    return std::clamp(c, 0L, cells[k] - 1);
  };
  auto key = [&](const std::array<long, 3>& c) { return (c[2] * cells[1] + c[1]) * cells[0] + c[0]; };
  std::unordered_map<long, std::vector<int>> grid;
  for (int i = 0; i < n; ++i) {
    std::array<long, 3> c{0, 0, 0};
    for (int k = 0; k < D; ++k) c[k] = cell_of(i, k);
    grid[key(c)].push_back(i);
  }
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (int i = 0; i < n; ++i) {
    std::array<long, 3> c{0, 0, 0};
    for (int k = 0; k < D; ++k) c[k] = cell_of(i, k);
    std::array<long, 3> o{-1, -1, -1}, nc{0, 0, 0};
    for (o[2] = D > 2 ? -1 : 0; o[2] <= (D > 2 ? 1 : 0); ++o[2])
      for (o[1] = D > 1 ? -1 : 0; o[1] <= (D > 1 ? 1 : 0); ++o[1])
        for (o[0] = -1; o[0] <= 1; ++o[0]) {
          bool ok = true;
          for (int k = 0; k < D; ++k) {
            nc[k] = c[k] + o[k];
            if (nc[k] < 0 || nc[k] >= cells[k]) {
              if (!wrap[k]) ok = false;
              nc[k] = (nc[k] + cells[k]) % cells[k];
            }
          }
          if (!ok) continue;
          const auto it = grid.find(key(nc));
          if (it == grid.end()) continue;
          for (int j : it->second) {
            if (j <= i) continue;
            double r2 = 0;
            for (int k = 0; k < D; ++k) {
              double d = x[gas[i] * D + k] - x[gas[j] * D + k];
              if (wrap[k]) {
                const double L = sc.upper[k] - sc.lower[k];
                d -= L * std::round(d / L);
              }
              r2 += d * d;
            }
            if (r2 < rc * rc) parent[root(parent, i)] = root(parent, j);
          }
        }
  }
  const int a = region.flow_axis;
  std::vector<char> at_inlet(n, 0);
  for (int i = 0; i < n; ++i)
    if (x[gas[i] * D + a] - region.lower[a] < rc) at_inlet[root(parent, i)] = 1;
  for (int i = 0; i < n; ++i)
    if (region.upper[a] - x[gas[i] * D + a] < rc && at_inlet[root(parent, i)]) return true;
  return false;
}

TwoPhaseSample sample_two_phase(const Scene& sc, const MonitorRegion& region, const std::vector<double>& x,
                                const std::vector<double>& v, const std::vector<double>& p,
                                const std::vector<double>& volume, const std::vector<double>& material) {
  const int D = sc.dimension, n = static_cast<int>(volume.size());
  TwoPhaseSample s;
  double vol[2] = {0, 0}, pv[2] = {0, 0}, vv[2][3] = {{0, 0, 0}, {0, 0, 0}};
  std::vector<int> gas;
  for (int i = 0; i < n; ++i) {
    if (sc.materials[static_cast<int>(material[i])].props.kind != MaterialKind::Fluid) continue;
    if (!inside(region, &x[i * D], D)) continue;
    const int g = phase_of(sc.materials[static_cast<int>(material[i])].props) == Phase::Gas ? 1 : 0;
    if (g) gas.push_back(i);
    vol[g] += volume[i];
    pv[g] += volume[i] * (p[i] - sc.materials[static_cast<int>(material[i])].props.background_pressure);
    for (int k = 0; k < D; ++k) vv[g][k] += volume[i] * v[i * D + k];
  }
  const double total = vol[0] + vol[1];
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double region_volume = 1;
  for (int k = 0; k < D; ++k) region_volume *= region.upper[k] - region.lower[k];
  s.porosity = region_volume > 0 ? total / region_volume : nan;
  s.saturation_liquid = total > 0 ? vol[0] / total : nan;
  s.saturation_gas = total > 0 ? vol[1] / total : nan;
  s.pressure_liquid = vol[0] > 0 ? pv[0] / vol[0] : nan;
  s.pressure_gas = vol[1] > 0 ? pv[1] / vol[1] : nan;
  for (int k = 0; k < D; ++k) {
    s.velocity_liquid[k] = vol[0] > 0 ? vv[0][k] / vol[0] : nan;
    s.velocity_gas[k] = vol[1] > 0 ? vv[1][k] / vol[1] : nan;
  }
  s.percolated = gas_percolates(sc, region, x, gas);
  return s;
}

TwoPhaseMonitor::TwoPhaseMonitor(const Scene& sc, const MonitorRegion& region, double stress_scale)
    : sc_(sc), region_(region), capillary_speed_(capillary_speed(sc)), stress_scale_(stress_scale),
      s_perc_(std::numeric_limits<double>::quiet_NaN()) {}

std::vector<std::string> TwoPhaseMonitor::columns() const {
  const char* axes = "xyz";
  std::vector<std::string> c = {"saturation_liquid", "saturation_gas", "porosity", "pressure_liquid", "pressure_gas",
                                "capillary_pressure"};
  for (const char* phase : {"liquid", "gas"})
    for (int k = 0; k < sc_.dimension; ++k) c.push_back(std::string("velocity_") + phase + "_" + axes[k]);
  c.push_back("percolation_time");
  if (capillary_speed_ > 0) c.push_back("v_max_over_sigma_mu");
  if (stress_scale_ > 0)
    for (const char* p : {"pressure_liquid_MPa", "pressure_gas_MPa", "capillary_pressure_MPa"}) c.push_back(p);
  return c;
}

std::vector<double> TwoPhaseMonitor::sample(Engine& e) {
  const std::vector<double> x = e.field("position"), v = e.field("velocity"), p = e.field("pressure");
  const std::vector<double> mat = e.field("material");
  last_ = sample_two_phase(sc_, region_, x, v, p, particle_volumes(e), mat);
  if (last_.percolated && t_perc_ < 0) t_perc_ = e.time(), s_perc_ = last_.saturation_gas;
  std::vector<double> row = {last_.saturation_liquid, last_.saturation_gas, last_.porosity, last_.pressure_liquid,
                             last_.pressure_gas, last_.pressure_gas - last_.pressure_liquid};
  for (const auto* u : {&last_.velocity_liquid, &last_.velocity_gas})
    for (int k = 0; k < sc_.dimension; ++k) row.push_back((*u)[k]);
  row.push_back(t_perc_ >= 0 ? t_perc_ : std::numeric_limits<double>::quiet_NaN());
  if (capillary_speed_ > 0) {
    double vmax = 0;
    for (std::size_t i = 0; i < mat.size(); ++i) {
      if (sc_.materials[static_cast<int>(mat[i])].props.kind != MaterialKind::Fluid) continue;
      double v2 = 0;
      for (int k = 0; k < sc_.dimension; ++k) v2 += v[i * sc_.dimension + k] * v[i * sc_.dimension + k];
      vmax = std::max(vmax, std::sqrt(v2));
    }
    row.push_back(vmax / capillary_speed_);
  }
  if (stress_scale_ > 0)
    for (const double p : {last_.pressure_liquid, last_.pressure_gas, last_.pressure_gas - last_.pressure_liquid})
      row.push_back(p * stress_scale_ * 1e-6);
  return row;
}

}  // namespace psph
