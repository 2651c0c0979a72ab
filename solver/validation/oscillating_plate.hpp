#pragma once
// First bending mode of a cantilever plate (cases/oscillating_plate_2d.toml; Gray, Monaghan &
// Swift 2001): the plate starts straight with the velocity of the Euler-Bernoulli mode,
//   v_y = V c f(x) / f(L),  f(x) = cos kx - cosh kx - (cos kL + cosh kL) / (sin kL + sinh kL) (sin kx - sinh kx),
// kL = 1.875, and vibrates at w^2 = E H^2 k^4 / (12 rho (1 - nu^2)) (plane strain). The period is
// read from the zero crossings of the modal coordinate sum_i u_y,i f(x_i).
#include <string>

#include "scene/case_file.hpp"

namespace psph {

// The plate with its initial velocity; `speed_ratio` is V (the tip speed over the P-wave speed);
// `spacing` > 0 replaces the case's (the support keeps its size in spacings). The displacement
// form takes nu = 0.2 (below its bound of 1/4).
Case oscillating_plate_case(double speed_ratio = 0.001, double spacing = 0,
                            SolidFormulation form = SolidFormulation::Stress);

struct PlateVibration {
  double omega = 0;         // measured (rad/s)
  double omega_exact = 0;   // Euler-Bernoulli
  double energy_drift = 0;  // max |E(t) / E(0) - 1|, E = kinetic + elastic
  double tip_amplitude = 0; // largest |u_y| of the free end (m)
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};

PlateVibration run_oscillating_plate(const Case& c, const std::string& backend);

}  // namespace psph
