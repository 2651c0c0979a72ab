#pragma once
// Weakly compressible equations of state.
#include <cmath>

#include "fluid/material.hpp"

namespace psph {

// p(rho) for material `mat` with reference density rho0.
//   linear: p = c^2 (rho - rho0)                                   Pazdniakou 2018 eq. 4
//   Tait:   p = rho0 c^2 / gamma ((rho/rho0)^gamma - 1)            (Monaghan 1994; Batchelor)
PSPH_HD inline Real pressure_from_density(const Material& mat, Real rho, Real rho0) {
  const Real c2 = mat.sound_speed * mat.sound_speed;
  if (mat.eos == EquationOfState::Tait)
    return rho0 * c2 / mat.tait_gamma * (pow(rho / rho0, mat.tait_gamma) - Real(1));
  return c2 * (rho - rho0);
}

}  // namespace psph
