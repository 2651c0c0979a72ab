#pragma once
// The region the two-phase monitors look at ([monitors] in a case file; monitors/two_phase.hpp).
#include <array>

namespace psph {

struct MonitorRegion {
  std::array<double, 3> lower{0, 0, 0}, upper{0, 0, 0};  // default: the domain
  int flow_axis = 0;                // inlet at lower[flow_axis], outlet at upper[flow_axis]
  double percolation_distance = 0;  // gas particles closer than this are connected (m)
};

}  // namespace psph
