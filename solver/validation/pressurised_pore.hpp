#pragma once
// Water pressurised in a lens-shaped pore in clay (cases/pressurised_pore_2d.toml), the block's
// faces under a confining stress: where the clay's damage starts (Deptulski 2021 Fig. 5.4,
// Pazdniakou 2018 Fig. 11: at the pore's tips) and at which pore pressure. Looked at every 5 kPa
// of pressure rise: the onset is the first clay particle with D > 1e-3; the run goes on until
// both tips have damage within a support.
#include <string>

#include "scene/case_file.hpp"

namespace psph {

// `confinement` (Pa, compression positive) on the four faces; `spacing` replaces the case's 1 mm
// (the support keeps its two spacings).
Case pressurised_pore_case(double confinement, double spacing = 1e-3);

struct PoreDamage {
  double onset_pressure = -1;       // the pore water's mean pressure at the onset (Pa); -1: none
  double onset_x = 0, onset_y = 0;  // reference position of the first damaged particle (m)
  double tip_distance = 0;          // its distance from the nearer tip (m)
  double other_tip_pressure = -1;   // the mean pressure when the other tip damages too (Pa)
  double compressive = 0;           // the largest compressive damage D_c at the onset
  double kinetic_over_elastic = 0;  // at the last look before the onset
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};

PoreDamage run_pressurised_pore(const Case& c, const std::string& backend);

}  // namespace psph
