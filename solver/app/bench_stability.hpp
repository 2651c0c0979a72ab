#pragma once
// Numerical stability, stress-tested (`poresph bench --stability`): the time-step factor and the
// initial particle disorder swept on the dam break and on the plane Poiseuille flow.
#include <ostream>
#include <string>
#include <vector>

namespace psph {

struct StabilityRecord {
  std::string case_name;
  double dt_factor = 1, jitter = 0;  // jitter: initial disorder as a fraction of the spacing
  bool stable = false;
  std::string diagnostic;            // why it stopped, when unstable
  double end_time = 0, density_deviation_max = 0, seconds = 0;
  long steps = 0;
};

// `only`: the cases to sweep (their names, e.g. oscillating_plate_2d); empty: every case.
std::vector<StabilityRecord> stability_sweep(const std::string& backend, bool quick, std::ostream* log,
                                             const std::vector<std::string>& only = {});

}  // namespace psph
