#pragma once
// The exact local update of the thermodynamic damage models (Deptulski 2021 eqs. 4.14, 4.19):
// the damage D* at which the loading function f = Y(D) - Y_c(D) vanishes for the current driving
// energy w~, in closed form, then D_new = min(s_l, max(D_old, D*)). Y decreases and Y_c does not
// decrease with D, so f < 0 (elastic, or unloading) is exactly D* < D_old, which keeps D_old
// (irreversibility, eq. 4.7). Solving f = 0 directly is the rate form (4.20) integrated exactly:
// no sub-steps, and no drift off f = 0 as an explicit integration of (4.20) would have.
#include <cmath>

#include "damage/driving_force.hpp"

namespace psph {

// D* for AT-1: 2 (1 - D) w~ = Y_c0, D* = 1 - Y_c0 / (2 w~) (0 below the onset 2 w~ = Y_c0).
PSPH_HD inline Real at1_threshold_damage(Real w, Real yc0) {
  return Real(2) * w > yc0 ? Real(1) - yc0 / (Real(2) * w) : Real(0);
}

// D* for AT-2: 2 (1 - D) w~ = 2 D Y_c0, D* = w~ / (w~ + Y_c0): no elastic range.
PSPH_HD inline Real at2_threshold_damage(Real w, Real yc0) { return w / (w + yc0); }

// D* for PCW with Y_c = Y_c0: (alpha + beta) w~ / (1 + beta D)^2 = Y_c0.
PSPH_HD inline Real pcw_threshold_damage(Real w, Real yc0, Real alpha, Real beta) {
  const Real r = sqrt((alpha + beta) * w / yc0);
  return r > Real(1) ? (r - Real(1)) / beta : Real(0);
}

// D* for PCW with Y_c = 2 D Y_c0: 2 Y_c0 D (1 + beta D)^2 = (alpha + beta) w~, a cubic in
// u = 1 + beta D: u^3 - u^2 - q = 0, q = beta (alpha + beta) w~ / (2 Y_c0), whose one real root
// u >= 1 is Cardano's with u = 1/3 + c + 1/(9 c), c^3 = 1/27 + q/2 + s, s^2 = q/27 + q^2/4.
// u - 1 = (3c - 1)^2 / (9c) and 3c - 1 = 27 (q/2 + s) / (9c^2 + 3c + 1): no cancellation at small q.
PSPH_HD inline Real pcw_linear_threshold_damage(Real w, Real yc0, Real alpha, Real beta) {
  const Real q = beta * (alpha + beta) * w / (Real(2) * yc0);
  const Real s = sqrt(q / Real(27) + q * q / Real(4));
  const Real c = cbrt(Real(1) / Real(27) + q / Real(2) + s);
  const Real m = Real(27) * (q / Real(2) + s) / (Real(9) * c * c + Real(3) * c + Real(1));
  return m * m / (Real(9) * c * beta);
}

// D* of the material's model for driving energy w~ (may lie below the current damage).
PSPH_HD inline Real threshold_damage(const ThermodynamicDamage& m, Real w) {
  if (m.degradation == Degradation::Quadratic)
    return m.linear_critical_energy ? at2_threshold_damage(w, m.critical_energy) : at1_threshold_damage(w, m.critical_energy);
  return m.linear_critical_energy ? pcw_linear_threshold_damage(w, m.critical_energy, m.alpha, m.beta)
                                  : pcw_threshold_damage(w, m.critical_energy, m.alpha, m.beta);
}

// The new damage of a point at strain eps that had `damage`: irreversible and below s_l.
template <int D>
PSPH_HD inline Real thermodynamic_damage_update(const ThermodynamicDamage& m, Real damage, const Mat<D>& eps, Real k0,
                                                Real mu0) {
  const Real target = threshold_damage(m, driving_energy(eps, k0, mu0, m.unilateral));
  const Real grown = target > damage ? target : damage;
  return grown < m.bound ? grown : m.bound;
}

}  // namespace psph
