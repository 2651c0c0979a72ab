#pragma once
// The interface stage's options ([interface]): interface/surface_tension.hpp.

namespace psph {

struct InterfaceOptions {
  double surface_tension = 0;      // sigma (N/m); 0 = no colour, normal or curvature pass
  double normal_threshold = 0.01;  // a normal is reliable when |grad c| > this / smoothing length
  bool geometric_wetting = true;   // walls' colour extrapolated (interface/wall_wetting.hpp), else cos(theta)
  bool contact_line_force = true;  // the unbalanced Young force at contact lines (interface/contact_line.hpp)
};

}  // namespace psph
