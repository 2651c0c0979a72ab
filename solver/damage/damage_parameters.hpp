#pragma once
// The laws' constants for one material, in working precision, from the case's options (host side;
// the results are passed by value to the passes).
#include <cmath>

#include "core/material.hpp"
#include "damage/damage_options.hpp"
#include "damage/degradation.hpp"
#include "damage/rankine_mohr_coulomb.hpp"

namespace psph {

inline RankineMohrCoulomb rankine_mohr_coulomb_parameters(const DamageOptions& o) {
  RankineMohrCoulomb p;
  p.tensile_strength = Real(o.tensile_strength);
  p.compressive_strength = Real(o.compressive_strength);
  const double s = std::sin(o.friction_angle);
  p.friction_factor = Real((1 + s) / (1 - s));
  p.tensile_elastic_strain = Real(o.tensile_elastic_strain);
  p.tensile_ultimate_strain = Real(o.tensile_ultimate_strain);
  p.compressive_elastic_strain = Real(o.compressive_elastic_strain);
  p.residual_tensile_strength = Real(o.residual_tensile_strength);
  p.residual_compressive_strength = Real(o.residual_compressive_strength);
  p.mazars = o.damage_combination == DamageCombination::Mazars;
  p.relaxation_rate = Real(1 / o.relaxation_steps);
  p.irreversible = o.damage_irreversible;
  return p;
}

// AT-1: quadratic, constant Y_c (Deptulski eq. 4.30a); AT-2: quadratic, Y_c = 2 D Y_c0 (4.30b);
// PCW: eq. 4.21 with either Y_c, and by default Y_c0 = E0 eps_0 eps_u / 2 of this material.
inline ThermodynamicDamage thermodynamic_parameters(const DamageOptions& o, const Material& m) {
  ThermodynamicDamage t;
  const bool pcw = o.damage_model == DamageModel::Pcw;
  t.degradation = pcw ? Degradation::Pcw : Degradation::Quadratic;
  t.linear_critical_energy = o.damage_model == DamageModel::At2 ||
                             (pcw && o.critical_energy_law == CriticalEnergyLaw::Linear);
  t.unilateral = o.unilateral;
  t.alpha = Real(o.pcw_alpha), t.beta = Real(o.pcw_beta);
  t.critical_energy = Real(pcw && o.critical_energy_from_strains
                               ? 0.5 * young_modulus<double>(m.bulk_modulus, m.shear_modulus) * o.elastic_limit_strain * o.ultimate_strain
                               : o.critical_energy_release);
  t.bound = Real(o.damage_bound);
  return t;
}

}  // namespace psph
