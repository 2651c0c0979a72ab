#pragma once
// Run time against error (`poresph bench --accuracy`): the validation cases over several kernels
// and resolutions, so that the cheapest set-up for a wanted accuracy can be read off.
#include <ostream>
#include <string>
#include <vector>

namespace psph {

struct AccuracyRecord {
  std::string case_name, kernel;
  double support_per_spacing = 0;
  int particles = 0;
  long steps = 0;
  double seconds = 0;
  double error = 0;  // Poiseuille-Couette: max over the paper's times of max|v - v_exact|/v_peak;
                     // spheres: |K/K_a - 1|
};

// `spheres`: also the sphere arrays (minutes per run on a CPU).
std::vector<AccuracyRecord> accuracy_sweep(const std::string& backend, bool spheres, std::ostream* log);

}  // namespace psph
