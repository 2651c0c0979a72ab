#pragma once
// Pressure probes ([[probe]] in a case file): the fluid's pressure at fixed points, each a column
// `pressure_<name>` of monitors.csv. A probe reads the Shepard (kernel-normalised) mean of the
// fluid particles within one support radius, sum_j W_ij V_j p_j / sum_j W_ij V_j, the observer of
// SPHinXsys and of the SPHERIC dam-break sensors; a probe with no fluid in reach reads 0 (dry).
// Computed on the host from the downloaded fields, at the monitor cadence only.
#include <array>
#include <string>
#include <vector>

#include "engine/engine.hpp"
#include "engine/scene.hpp"

namespace psph {

struct Probe {
  std::string name;
  std::array<double, 3> position{0, 0, 0};
};

// Each probe's pressure from particle fields (components interleaved, D per particle).
std::vector<double> probe_pressures(const Scene& sc, const std::vector<Probe>& probes, const std::vector<double>& x,
                                    const std::vector<double>& p, const std::vector<double>& volume,
                                    const std::vector<double>& material);

// The columns pressure_<name>, and the row for the engine's current state.
std::vector<std::string> probe_columns(const std::vector<Probe>& probes);
std::vector<double> sample_probes(Engine& e, const Scene& sc, const std::vector<Probe>& probes);

}  // namespace psph
