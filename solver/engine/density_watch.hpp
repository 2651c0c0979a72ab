#pragma once
// The fluid's weak compressibility as a run goes (GUIDE §3: WCSPH holds while the density varies
// by about 1 %): the largest |rho/rho0 - 1| of any fluid particle at any step, and where and when it
// first passed the case's bound (solver.max_density_deviation).
#include <string>

namespace psph {

struct DensityExceedance {
  double time = -1;  // s; < 0: never
  long step = 0;
  double value = 0;   // |rho/rho0 - 1| then
  std::string where;  // the particle: id, material, position, speed
};

struct DensityWatch {
  double bound = 0.03;
  double peak = 0, peak_time = 0;  // the largest deviation since the engine was made (or restarted)
  long peak_step = 0;
  DensityExceedance first;  // the first step past `bound`
  bool exceeded() const { return first.time >= 0; }
};

// The largest deviation any engine of this process reached since the last take: what `poresph
// validate` records for each case, whichever engines the case made; -1 when none had a fluid.
void note_density_deviation(double value);
double take_density_deviation_peak();

}  // namespace psph
