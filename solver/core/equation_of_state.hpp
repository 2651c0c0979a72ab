#pragma once
// Weakly compressible equations of state.
#include <cmath>

#include "core/material.hpp"

namespace psph {

// p(rho) for material `mat` with reference density rho0, plus the background pressure p_b:
//   linear: p = c^2 (rho - rho0) + p_b                             Pazdniakou 2018 eq. 4
//   Tait:   p = rho0 c^2 / gamma ((rho/rho0)^gamma - 1) + p_b      (Monaghan 1994; Batchelor)
// A background pressure keeps a gas that must carry a liquid's pressure drop from going negative.
PSPH_HD inline Real pressure_from_density(const Material& mat, Real rho, Real rho0) {
  const Real c2 = mat.sound_speed * mat.sound_speed;
  if (mat.eos == EquationOfState::Tait)
    return rho0 * c2 / mat.tait_gamma * (pow(rho / rho0, mat.tait_gamma) - Real(1)) + mat.background_pressure;
  return c2 * (rho - rho0) + mat.background_pressure;
}

// The inverse of pressure_from_density: the density at which material `mat` has pressure p_abs.
PSPH_HD inline Real density_from_pressure(const Material& mat, Real p_abs, Real rho0) {
  const Real p = p_abs - mat.background_pressure;
  const Real c2 = mat.sound_speed * mat.sound_speed;
  if (mat.eos == EquationOfState::Tait) {
    const Real base = Real(1) + p * mat.tait_gamma / (rho0 * c2);
    return rho0 * pow(base > Real(1e-6) ? base : Real(1e-6), Real(1) / mat.tait_gamma);
  }
  return rho0 + p / c2;
}

}  // namespace psph
