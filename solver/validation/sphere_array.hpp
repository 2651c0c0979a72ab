#pragma once
// Permeability of a periodic simple-cubic sphere array (Pazdniakou 2018 §4.2): the case
// cases/sphere_array.toml at any solid fraction, spacing and kernel, run to steady state.
#include <ostream>
#include <string>

#include "scene/case_file.hpp"

namespace psph {

// K_a (m^2) for the three solid fractions of the paper (Pazdniakou 2018 Table 2, eqs. 79-81,
// after Sangani & Acrivos 1982).
double sphere_array_reference(double solid_fraction);

// The case with the sphere radius for `solid_fraction`, spacing = support / support_per_spacing.
Case sphere_array_case(double solid_fraction, double support_per_spacing, const std::string& kernel = "cubic_spline");

struct Permeability {
  double K = 0;        // m^2, mu <v_z> / (rho g), <v_z> superficial
  double time = 0;     // simulated time to steady state (s)
  long steps = 0;
  int particles = 0;
  double seconds = 0;  // wall time
};

// Runs until <v_z> changes by less than 0.5 % over 0.05 s (or 5 s): the plateau once the
// start-up transient has decayed. Past it K drifts down slowly (the fluid layer against the sphere
// compacts; VALIDATION.md), so the plateau is the measurement.
Permeability measure_permeability(const Case& c, const std::string& backend);

}  // namespace psph
