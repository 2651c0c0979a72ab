#pragma once
// The stress of a damaged point, from the small strain (or, in large strain, the Green-Lagrange
// strain, giving the second Piola-Kirchhoff stress: Deptulski 2021 §4.1 replaces the tensors).
#include "damage/damage_options.hpp"
#include "damage/degradation.hpp"
#include "solid/constitutive.hpp"

namespace psph {

// The bulk modulus of the thermodynamic models: k0 g(D), or k0 while tr eps < 0 with crack
// closure (Deptulski eq. 4.18a). Continuous at tr eps = 0, where the bulk term vanishes.
PSPH_HD inline Real thermodynamic_bulk_modulus(const ThermodynamicDamage& m, Real tr_eps, Real k0, Real damage) {
  return (m.unilateral && tr_eps < Real(0)) ? k0 : k0 * degradation(m, damage);
}

// sigma = k tr(eps) I + 2 mu0 g(D) eps^d (Deptulski eq. 4.18a).
template <int D>
PSPH_HD inline Mat<D> thermodynamic_stress(const ThermodynamicDamage& m, const Mat<D>& eps, Real k0, Real mu0,
                                           Real damage) {
  const Real k = thermodynamic_bulk_modulus(m, trace(eps), k0, damage);
  return small_strain_stress(eps, k, mu0 * degradation(m, damage));
}

// The Rankine-Mohr-Coulomb D in the stress (how: Pazdniakou 2018 §2.2.2, §5.2.3): by default
// sigma = k0 tr(eps) I + 2 mu0 (1 - D) eps^d, the volumetric (pressure) part intact so that the
// solid keeps its volume; with AllModuli (1 - D) sigma0 (eq. 18 with nu fixed). A ghost (below)
// takes the deviatoric law until it drops out.
template <int D>
PSPH_HD inline Mat<D> rankine_mohr_coulomb_stress(DamageDegrades how, const Mat<D>& eps, Real k0, Real mu0, Real damage) {
  const Real keep = Real(1) - damage;
  return small_strain_stress(eps, how == DamageDegrades::AllModuli ? k0 * keep : k0, mu0 * keep);
}

// A particle that drops out of every interaction (Pazdniakou Fig. 14d).
PSPH_HD inline bool is_damage_ghost(DamageDegrades how, Real threshold, Real damage) {
  return how == DamageDegrades::Ghost && damage >= threshold;
}

}  // namespace psph
