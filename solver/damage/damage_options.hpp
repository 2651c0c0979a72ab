#pragma once
// The damage models' options ([damage]): which law, on which elastic materials, and its
// parameters in SI. Defaults are the references' values and, where they give none, the choices
// noted beside each parameter.

namespace psph {

// rankine_mohr_coulomb: Pazdniakou 2018 eqs. 18-24 (damage/rankine_mohr_coulomb.hpp).
// at1, at2, pcw: Deptulski 2021 eqs. 4.17-4.23, 4.27 (damage/thermodynamic_update.hpp).
enum class DamageModel { None, RankineMohrCoulomb, At1, At2, Pcw };
// Pazdniakou eq. 23: Mazars weights zeta_t, zeta_c, or max(D_t, D_c).
enum class DamageCombination { Mazars, Max };
// How the Rankine-Mohr-Coulomb D enters the stress: the deviatoric part only (Pazdniakou §5.2.3,
// damaged particles keep their pressure term), all moduli (eq. 18 literally), or deviatoric
// only and particles at or above a threshold drop out of every interaction (its Fig. 14d).
enum class DamageDegrades { Deviatoric, AllModuli, Ghost };
// Deptulski eq. 4.23: Y_c = Y_c0 (a) or Y_c = 2 D Y_c0 (b).
enum class CriticalEnergyLaw { Constant, Linear };

struct DamageOptions {
  DamageModel damage_model = DamageModel::None;
  unsigned damage_materials = 0;  // bit k set: material k damages (elastic materials only)
  bool damages(int material) const { return damage_model != DamageModel::None && (damage_materials >> material & 1u); }

  // Rankine-Mohr-Coulomb (Pazdniakou 2018 Table 1, COx clay).
  double tensile_strength = 4e6;             // f_t (Pa), eq. 19
  double compressive_strength = 20e6;        // f_c (Pa), eq. 21
  double friction_angle = 25 * 3.14159265358979323846 / 180;  // phi (rad), eq. 21
  double tensile_elastic_strain = 0.0013;    // eps_t0, eq. 20 (a magnitude)
  double tensile_ultimate_strain = 0.0026;   // eps_tu, eq. 20
  double compressive_elastic_strain = 0.015; // eps_c0, eq. 22
  // Residual strengths f_tr, f_cr (eqs. 20, 22; not given): 0.1 f_t and 0.1 f_c after Tang et
  // al. 2002, the paper's source for the law.
  double residual_tensile_strength = 0.4e6, residual_compressive_strength = 2e6;
  DamageCombination damage_combination = DamageCombination::Mazars;
  double relaxation_steps = 10;  // tau of eq. 24 (steps)
  bool damage_irreversible = false;  // the paper's main runs let particles heal
  DamageDegrades damage_degrades = DamageDegrades::Deviatoric;
  double ghost_threshold = 0.99;  // D at or above which a particle is a ghost

  // AT-1, AT-2, PCW (Deptulski 2021): always irreversible (eq. 4.7).
  double critical_energy_release = 2.5e3;  // Y_c0 (Pa = J/m^3): the plate's 2.5e-3 N/mm^2, Table 4.2
  CriticalEnergyLaw critical_energy_law = CriticalEnergyLaw::Constant;  // at2: Linear; pcw: either
  double damage_bound = 0.99;  // s_l, Table 4.2
  bool unilateral = true;      // eq. 4.17: the bulk modulus is degraded only while tr eps > 0
  // PCW, eq. 4.21 with 4.27: alpha = 1, beta = eps_u / eps_0 - 1; eps_u / eps_0 = 2 (beta = 1)
  // from the COx Table 5.1 strains, as in Ch. 5 and App. B.
  double pcw_alpha = 1, pcw_beta = 1;
  double elastic_limit_strain = 0.0013, ultimate_strain = 0.0026;  // eps_0, eps_u
  // Y_c0 = E0 eps_0 eps_u / 2 for each material (onset at eps_0, linear softening to eps_u): the
  // thesis prints no Y_c0 for its PCW runs; false when the case gives critical_energy_release.
  bool critical_energy_from_strains = true;
};

}  // namespace psph
