#pragma once
// Each particle's volume m / rho from an engine's fields, for the monitors that weigh by volume
// (monitors/pressure_probes.hpp, monitors/two_phase.hpp). Downloaded on monitor steps only.
#include <vector>

#include "engine/engine.hpp"

namespace psph {

inline std::vector<double> particle_volumes(Engine& e) {
  std::vector<double> volume = e.field("mass");
  const std::vector<double> rho = e.field("density");
  for (std::size_t i = 0; i < volume.size(); ++i) volume[i] /= rho[i];
  return volume;
}

}  // namespace psph
