#pragma once
// Permeability of a periodic simple-cubic sphere array (Pazdniakou 2018 §4.2): the case
// cases/sphere_array.toml at any solid fraction, spacing and kernel, run to steady state
// (validation/permeability.hpp: until <v_z> changes by less than 0.5 % over 0.05 s, or 5 s; past
// the plateau K drifts down slowly as the fluid layer against the sphere compacts, VALIDATION.md).
#include <ostream>
#include <string>

#include "scene/case_file.hpp"
#include "validation/permeability.hpp"

namespace psph {

// K_a (m^2) for the three solid fractions of the paper (Pazdniakou 2018 Table 2, eqs. 79-81,
// after Sangani & Acrivos 1982).
double sphere_array_reference(double solid_fraction);

// The case with the sphere radius for `solid_fraction`, spacing = support / support_per_spacing.
Case sphere_array_case(double solid_fraction, double support_per_spacing, const std::string& kernel = "cubic_spline");

}  // namespace psph
