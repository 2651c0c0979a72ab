#pragma once
// The stress of a damaged point, from the small strain (or, in large strain, the Green-Lagrange
// strain, giving the second Piola-Kirchhoff stress: Deptulski 2021 §4.1 replaces the tensors).
#include "damage/damage_options.hpp"
#include "damage/degradation.hpp"
#include "solid/constitutive.hpp"

namespace psph {

// The moduli of a damaged point; its stress is small_strain_stress(eps, k, mu) (in large strain
// of the Green-Lagrange strain), and the displacement form pairs them by harmonic means.
struct DamagedModuli {
  Real bulk, shear;
};

// The thermodynamic models (Deptulski eq. 4.18a): mu0 g(D), and k0 g(D), or k0 while tr eps < 0
// with crack closure. Continuous at tr eps = 0, where the bulk term vanishes.
PSPH_HD inline DamagedModuli thermodynamic_moduli(const ThermodynamicDamage& m, Real tr_eps, Real k0, Real mu0,
                                                  Real damage) {
  const Real g = degradation(m, damage);
  return {(m.unilateral && tr_eps < Real(0)) ? k0 : k0 * g, mu0 * g};
}

// The Rankine-Mohr-Coulomb D in the stress (how: Pazdniakou 2018 §2.2.2, §5.2.3): by default
// sigma = k0 tr(eps) I + 2 mu0 (1 - D) eps^d, the volumetric (pressure) part intact so that the
// solid keeps its volume; with AllModuli (1 - D) sigma0 (eq. 18 with nu fixed). A ghost (below)
// takes the deviatoric law until it drops out.
PSPH_HD inline DamagedModuli rankine_mohr_coulomb_moduli(DamageDegrades how, Real k0, Real mu0, Real damage) {
  const Real keep = Real(1) - damage;
  return {how == DamageDegrades::AllModuli ? k0 * keep : k0, mu0 * keep};
}

// The stresses of the two laws at strain eps.
template <int D>
PSPH_HD inline Mat<D> thermodynamic_stress(const ThermodynamicDamage& m, const Mat<D>& eps, Real k0, Real mu0,
                                           Real damage) {
  const DamagedModuli c = thermodynamic_moduli(m, trace(eps), k0, mu0, damage);
  return small_strain_stress(eps, c.bulk, c.shear);
}
template <int D>
PSPH_HD inline Mat<D> rankine_mohr_coulomb_stress(DamageDegrades how, const Mat<D>& eps, Real k0, Real mu0, Real damage) {
  const DamagedModuli c = rankine_mohr_coulomb_moduli(how, k0, mu0, damage);
  return small_strain_stress(eps, c.bulk, c.shear);
}

// A particle that drops out of every interaction (Pazdniakou Fig. 14d).
PSPH_HD inline bool is_damage_ghost(DamageDegrades how, Real threshold, Real damage) {
  return how == DamageDegrades::Ghost && damage >= threshold;
}

}  // namespace psph
