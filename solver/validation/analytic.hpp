#pragma once
// Analytical solutions the validation cases compare against.

namespace psph {

// Transient Poiseuille-Couette flow from rest between a wall at x = 0 (at rest) and a wall at
// x = L moving at V, driven by a body force g along the walls (Pazdniakou 2018 eq. 77, with the
// series coefficient 2((-1)^n - 1) instead of the printed 2(-1)^n - 1, digest §7 item 3).
// nu = mu / rho. `terms` sine terms (the series converges like 1/n^2 at t = 0).
double poiseuille_couette_velocity(double x, double t, double L, double g, double V, double nu, int terms = 400);

}  // namespace psph
