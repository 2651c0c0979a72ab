#pragma once
// A body force on one fluid inside a box (`[[body_force_region]]`), e.g. the reservoir gas that
// drives a drainage through a periodic cell (Pazdniakou 2018 §5.2); the fluid stage ramps it.
#include <array>

namespace psph {

struct SceneForceRegion {
  int material = 0;
  std::array<double, 3> lower{0, 0, 0}, upper{0, 0, 0}, acceleration{0, 0, 0};
  double ramp_time = 0;  // s: the force grows linearly from zero over this time (0: full at once)
};

}  // namespace psph
