#pragma once
// Analytical solutions the validation cases compare against.

namespace psph {

// Transient Poiseuille-Couette flow from rest between a wall at x = 0 (at rest) and a wall at
// x = L moving at V, driven by a body force g along the walls (Pazdniakou 2018 eq. 77, with the
// series coefficient 2((-1)^n - 1) instead of the printed 2(-1)^n - 1, a typo).
// nu = mu / rho. `terms` sine terms (the series converges like 1/n^2 at t = 0).
double poiseuille_couette_velocity(double x, double t, double L, double g, double V, double nu, int terms = 400);

// Steady layered Poiseuille flow of gas (-l <= x <= 0) and liquid (0 <= x <= l) between walls at
// x = -l and x = l, driven by the same force per volume F in both (Pazdniakou 2018 eq. 82, with
// the ranges in l instead of the printed h, a typo).
double two_phase_poiseuille_velocity(double x, double l, double F, double mu_gas, double mu_liquid);

}  // namespace psph
