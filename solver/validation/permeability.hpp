#pragma once
// Absolute permeability from a body-force-driven single-phase run to steady state:
// K = mu q / (rho g), q the superficial (Darcy) velocity along the force over a bulk volume.
#include <string>

#include "scene/case_file.hpp"

namespace psph {

struct Permeability {
  double K = 0;        // m^2
  double time = 0;     // simulated time to steady state (s)
  long steps = 0;
  int particles = 0;
  double seconds = 0;  // wall time
};

struct PermeabilityRun {
  double bulk_volume = 0;  // m^3 the superficial velocity is over; 0: the domain's
  double interval = 0.05;  // s between the checks of q
  double min_time = 0.1;   // s before the first check may stop the run
  double max_time = 5.0;   // s
  double change = 5e-3;    // stop when q changes by less than this fraction over an interval
};

// The fluid's body force gives the flow axis (its largest component) and g.
Permeability measure_permeability(const Case& c, const std::string& backend, const PermeabilityRun& run = {});

}  // namespace psph
