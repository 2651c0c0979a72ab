#pragma once
// Two-phase monitors (monitors.csv, one row per monitor step): in a box region, the saturation of
// each phase, the porosity (the fluids' volume over the region's: Deptulski 2021 Fig. 5.6a), the
// mean phase pressures and the capillary pressure, the mean phase velocities (seepage velocities,
// Pazdniakou 2018 Fig. 12), the
// first time a connected gas cluster joins the region's inlet and outlet faces (percolation,
// Pazdniakou 2018 §5.2.2, Table 5; the paper does not define it, this is ours), and the largest
// speed relative to sigma/mu (the spurious currents of a static case). Computed on the host from
// the downloaded fields, at the monitor cadence only; present only in cases with a liquid and a gas.
#include <array>
#include <string>
#include <vector>

#include "engine/engine.hpp"
#include "monitors/monitor_region.hpp"
#include "engine/scene.hpp"

namespace psph {

struct TwoPhaseSample {
  double saturation_liquid = 0, saturation_gas = 0;  // fluid volume fractions in the region
  double porosity = 0;                               // fluid volume / region volume
  // volume-weighted means (Pa) over the fluids' initial background pressure ([solver])
  double pressure_liquid = 0, pressure_gas = 0;
  std::array<double, 3> velocity_liquid{0, 0, 0}, velocity_gas{0, 0, 0};  // volume-weighted means
  bool percolated = false;                           // a gas cluster joins inlet and outlet now
};

// One sample from particle fields (components interleaved, D per particle).
TwoPhaseSample sample_two_phase(const Scene& sc, const MonitorRegion& region, const std::vector<double>& x,
                                const std::vector<double>& v, const std::vector<double>& p,
                                const std::vector<double>& volume, const std::vector<double>& material);

// True when the gas particles listed in `gas` (indices into x) hold a cluster, linked by distances
// below region.percolation_distance (minimum image along periodic axes other than the flow axis),
// with a member within that distance of the inlet face and one of the outlet face.
bool gas_percolates(const Scene& sc, const MonitorRegion& region, const std::vector<double>& x,
                    const std::vector<int>& gas);

class TwoPhaseMonitor {
 public:
  // stress_scale > 0: the pressures also in physical MPa (columns *_MPa; Case::stress_scale).
  TwoPhaseMonitor(const Scene& sc, const MonitorRegion& region, double stress_scale = 0);
  std::vector<std::string> columns() const;
  // The row for the engine's current state (percolation_time is NaN until gas percolates).
  std::vector<double> sample(Engine& e);
  double percolation_time() const { return t_perc_; }  // < 0: not yet
  double saturation_at_percolation() const { return s_perc_; }  // gas saturation then (NaN: not yet)
  const TwoPhaseSample& last() const { return last_; }

 private:
  const Scene& sc_;
  MonitorRegion region_;
  double capillary_speed_ = 0;  // sigma / mu_liquid, 0 without surface tension
  double stress_scale_ = 0;
  double t_perc_ = -1, s_perc_;
  TwoPhaseSample last_;
};

}  // namespace psph
