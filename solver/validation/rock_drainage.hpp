#pragma once
// Gas drainage of a crop of the Berea sandstone image (cases/berea_drainage.toml), on any crop:
// the sleeve, the reservoirs, the forced regions and the monitored sample follow the crop.
#include <array>
#include <string>

#include "scene/case_file.hpp"

namespace psph {

struct RockDrainage {
  double percolation_time = -1;  // s, < 0: none before the end
  double saturation_gas = 0, capillary_pressure = 0;  // in the sample, then
  double driving_pressure = 0;   // Pa, rho g H over the reservoirs
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};

// The crop [lower, lower + size) of voxels, run until gas percolates or `end` (s).
Case berea_drainage_case(const std::array<long, 3>& lower, const std::array<long, 3>& size, double end);
RockDrainage run_rock_drainage(const Case& c, const std::string& backend);

}  // namespace psph
