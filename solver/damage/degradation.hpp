#pragma once
// The thermodynamic damage models of Deptulski 2021 §4.1 (AT-1, AT-2, PCW) for one material: the
// degradation g(D) = k(D)/k0 = mu(D)/mu0, its slope, the critical energy release Y_c(D) and the
// energy dissipated to reach D.
#include "core/vec.hpp"

namespace psph {

// (1 - D)^2 (eq. 4.22, AT-1 and AT-2) or (1 - alpha D) / (1 + beta D) (eq. 4.21, PCW).
enum class Degradation : int { Quadratic = 0, Pcw = 1 };

struct ThermodynamicDamage {
  Degradation degradation = Degradation::Quadratic;
  bool linear_critical_energy = false;  // Y_c = 2 D Y_c0 (eq. 4.23b), else Y_c0 (eq. 4.23a)
  bool unilateral = true;               // eq. 4.17
  Real alpha = 1, beta = 1;             // PCW, eq. 4.21
  Real critical_energy = 0;             // Y_c0 (Pa)
  Real bound = Real(0.99);              // s_l: D < s_l
};

PSPH_HD inline Real degradation(const ThermodynamicDamage& m, Real damage) {
  if (m.degradation == Degradation::Quadratic) return (Real(1) - damage) * (Real(1) - damage);
  return (Real(1) - m.alpha * damage) / (Real(1) + m.beta * damage);
}

// g'(D): -2 (1 - D), or -(alpha + beta) / (1 + beta D)^2.
PSPH_HD inline Real degradation_slope(const ThermodynamicDamage& m, Real damage) {
  if (m.degradation == Degradation::Quadratic) return Real(-2) * (Real(1) - damage);
  const Real q = Real(1) + m.beta * damage;
  return -(m.alpha + m.beta) / (q * q);
}

// Deptulski eq. 4.23.
PSPH_HD inline Real critical_energy(const ThermodynamicDamage& m, Real damage) {
  return m.linear_critical_energy ? Real(2) * damage * m.critical_energy : m.critical_energy;
}

// The energy density dissipated from 0 to D, the integral of Y_c dD: Y_c0 D (Deptulski eq.
// 4.26b), or Y_c0 D^2 with Y_c = 2 D Y_c0 (the thesis notes 4.26b must change there; this is
// its integral).
PSPH_HD inline Real dissipated_energy_density(const ThermodynamicDamage& m, Real damage) {
  return m.linear_critical_energy ? m.critical_energy * damage * damage : m.critical_energy * damage;
}

}  // namespace psph
