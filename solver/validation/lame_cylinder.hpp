#pragma once
// A thick-walled cylinder pressurised by the fluid inside it (cases/lame_cylinder_2d.toml; plane
// strain): once settled, the solid's radial and hoop stresses against Lame's
//   sigma_rr = A - B / r^2,  sigma_tt = A + B / r^2,  A = p a^2 / (b^2 - a^2),  B = A b^2,
// with p the fluid's mean pressure away from the wall and a, b the radii of the lattice's fluid
// and fluid + solid areas (a staircase circle holds N dx^2 of area).
#include <string>

#include "scene/case_file.hpp"

namespace psph {

// `spacing` > 0 replaces the case's (the support keeps its size in spacings).
Case lame_cylinder_case(double spacing = 0);

struct LameComparison {
  double pressure = 0;            // the fluid's (Pa)
  double inner = 0, outer = 0;    // a, b (m)
  double radial_error = 0;        // max |sigma_rr - Lame| / p over the compared particles
  double hoop_error = 0;          // max |sigma_tt - Lame| / p
  double radial_rms = 0, hoop_rms = 0;
  int compared = 0;               // particles a support and more from both surfaces
  double kinetic_energy = 0;      // at the end (J)
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};

LameComparison run_lame_cylinder(const Case& c, const std::string& backend);

}  // namespace psph
