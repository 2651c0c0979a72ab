#pragma once
// Tensile (Rankine) and compressive/shear (Mohr-Coulomb) damage of Pazdniakou 2018 §2.2.2
// (eqs. 19-24, after Tang et al. 2002 and Fall et al. 2014). The paper writes its criteria with
// compression positive (sigma_1 the most compressive principal stress, sigma_3 the most tensile);
// here principal values are tension positive, so its sigma_3 is -stress[0], its sigma_1 is
// -stress[2], and its strains eps_3, eps_1 are -strain[0], -strain[2]. Table 1 strains are
// magnitudes. The criteria see the stress of the intact moduli (the effective stress).
#include "core/material.hpp"
#include "damage/principal_state.hpp"

namespace psph {

// The law's constants, in working precision, for host and device.
struct RankineMohrCoulomb {
  Real tensile_strength = 0, compressive_strength = 0;  // f_t, f_c (Pa)
  Real friction_factor = 1;                             // (1 + sin phi) / (1 - sin phi), eq. 21
  Real tensile_elastic_strain = 0, tensile_ultimate_strain = 0, compressive_elastic_strain = 0;
  Real residual_tensile_strength = 0, residual_compressive_strength = 0;  // f_tr, f_cr (Pa)
  bool mazars = true;  // eq. 23 by Mazars weights, else max(D_t, D_c)
  Real relaxation_rate = Real(0.1);  // 1 / tau of eq. 24 (per step): a product, not a division, per point
  bool irreversible = false;
};

PSPH_HD inline Real clamp_unit(Real x) { return x < Real(0) ? Real(0) : x > Real(1) ? Real(1) : x; }

// Pazdniakou eq. 20 in tensile strain magnitude e: 0 up to eps_t0, 1 - f_tr / (E0 e) up to eps_tu,
// then 1 (clamped to [0, 1]: f_tr > E0 e would give a negative damage).
PSPH_HD inline Real rankine_damage(const RankineMohrCoulomb& p, Real young, Real e) {
  if (e <= p.tensile_elastic_strain) return Real(0);
  if (e > p.tensile_ultimate_strain) return Real(1);
  return clamp_unit(Real(1) - p.residual_tensile_strength / (young * e));
}

// Pazdniakou eq. 22 in compressive strain e: 0 up to eps_c0, then 1 - f_cr / (E0 e).
PSPH_HD inline Real mohr_coulomb_damage(const RankineMohrCoulomb& p, Real young, Real e) {
  if (e <= p.compressive_elastic_strain) return Real(0);
  return clamp_unit(Real(1) - p.residual_compressive_strength / (young * e));
}

// Pazdniakou eq. 19: sigma_3 <= -f_t.
PSPH_HD inline bool rankine_reached(const RankineMohrCoulomb& p, const PrincipalState& s) {
  return s.stress[0] >= p.tensile_strength;
}

// Pazdniakou eq. 21: sigma_1 - sigma_3 (1 + sin phi) / (1 - sin phi) >= f_c.
PSPH_HD inline bool mohr_coulomb_reached(const RankineMohrCoulomb& p, const PrincipalState& s) {
  return -s.stress[2] + s.stress[0] * p.friction_factor >= p.compressive_strength;
}

// The tensile weight zeta_t of eq. 23 (the paper refers to Mazars 1986 for it): the strains of
// the tensile and compressive parts of the principal stress, eps^t,c = [(1 + nu) sigma^+- -
// nu tr(sigma^+-)] / E0, and zeta_t = sum over eps_i > 0 of eps^t_i eps_i / sum of eps_i^2 (the
// Mazars & Pijaudier-Cabot 1989 form, which makes zeta_t + zeta_c = 1 exactly); zeta_c = 1 - zeta_t.
// A point with no extension is compressive only.
PSPH_HD inline Real mazars_tensile_weight(const PrincipalState& s, Real young, Real poisson) {
  Real tr_plus = 0;
  for (int k = 0; k < 3; ++k) tr_plus += s.stress[k] > Real(0) ? s.stress[k] : Real(0);
  Real num = 0, den = 0;  // num without its 1 / E0: one division for the point
  for (int k = 0; k < 3; ++k) {
    if (!(s.strain[k] > Real(0))) continue;
    const Real plus = s.stress[k] > Real(0) ? s.stress[k] : Real(0);
    num += ((Real(1) + poisson) * plus - poisson * tr_plus) * s.strain[k];
    den += s.strain[k] * s.strain[k];
  }
  return den > Real(0) ? clamp_unit(num / (young * den)) : Real(0);
}

// The damages of eqs. 20 and 22 at this state (D_t where eq. 19 holds, D_c where eq. 21 holds)
// and their combination, the target of eq. 23.
struct RankineMohrCoulombTarget {
  Real tensile = 0, compressive = 0, combined = 0;
};
PSPH_HD inline RankineMohrCoulombTarget rankine_mohr_coulomb_parts(const RankineMohrCoulomb& p, const PrincipalState& s,
                                                                   Real k0, Real mu0) {
  Real young, poisson;
  young_and_poisson(k0, mu0, young, poisson);
  RankineMohrCoulombTarget t;
  t.tensile = rankine_reached(p, s) ? rankine_damage(p, young, s.strain[0]) : Real(0);
  t.compressive = mohr_coulomb_reached(p, s) ? mohr_coulomb_damage(p, young, -s.strain[2]) : Real(0);
  if (!p.mazars) {
    t.combined = t.tensile > t.compressive ? t.tensile : t.compressive;
  } else {
    const Real zt = mazars_tensile_weight(s, young, poisson);
    t.combined = zt * t.tensile + (Real(1) - zt) * t.compressive;
  }
  return t;
}
PSPH_HD inline Real rankine_mohr_coulomb_target(const RankineMohrCoulomb& p, const PrincipalState& s, Real k0, Real mu0) {
  return rankine_mohr_coulomb_parts(p, s, k0, mu0).combined;
}

// Pazdniakou eq. 24: D relaxes towards the target by 1/tau of the gap per step; irreversible, it
// only grows.
PSPH_HD inline Real relaxed_damage(const RankineMohrCoulomb& p, Real damage, Real target) {
  const Real next = damage + (target - damage) * p.relaxation_rate;
  return (p.irreversible && next < damage) ? damage : next;
}

// One step of the law at strain eps for a point that had `damage` (its target and parts in
// `target`, if given).
template <int D>
PSPH_HD inline Real rankine_mohr_coulomb_update(const RankineMohrCoulomb& p, Real damage, const Mat<D>& eps, Real k0,
                                                Real mu0, RankineMohrCoulombTarget* target = nullptr) {
  const RankineMohrCoulombTarget t = rankine_mohr_coulomb_parts(p, principal_state(eps, k0, mu0), k0, mu0);
  if (target) *target = t;
  return relaxed_damage(p, damage, t.combined);
}

}  // namespace psph
