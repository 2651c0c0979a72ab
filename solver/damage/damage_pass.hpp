#pragma once
// The damage stage's pass (damage/damage_stage.hpp), after the strain pass of the elastic stage:
// each damaging particle's new damage from its strain (the Green-Lagrange strain in large
// strain), its driving force, and its stress with the degraded moduli in place of the intact one
// (the Cauchy stress, and in large strain the Piola stress the force pass reads); in the
// displacement form also the degraded moduli, which its pair forces read; with ghosts, which
// particles become one (damage/ghosts.hpp).
#include "core/material.hpp"
#include "damage/damage_options.hpp"
#include "damage/degraded_stress.hpp"
#include "damage/driving_force.hpp"
#include "damage/rankine_mohr_coulomb.hpp"
#include "damage/thermodynamic_update.hpp"
#include "state/particles.hpp"
#include "core/pass_fields.hpp"

namespace psph {

// What the pass needs of the case, by value.
struct DamageLaw {
  bool rankine = false;  // else the thermodynamic models
  unsigned materials = 0;  // bit k: material k damages
  RankineMohrCoulomb rmc;
  DamageDegrades degrades = DamageDegrades::Deviatoric;
  Real ghost_threshold = 1;  // degraded = "ghost": the damage at which a particle becomes one
  ThermodynamicDamage thermo[kMaxMaterials];  // per material (PCW's Y_c0 follows each E0)
  PSPH_HD bool damages(int material) const { return materials >> material & 1u; }
};

template <int D>
struct DamageUpdatePass {
  static constexpr FieldNames neighbour_reads{};
  static constexpr FieldNames writes{"damage",          "damage_driving_force", "tensile_damage",
                                     "compressive_damage", "damaged_bulk_modulus", "damaged_shear_modulus",
                                     "damage_ghost",    "stress"};
  ParticleView<D> s;
  MaterialTable<D> mats;
  DamageLaw law;
  Real* damage;
  Real* driving_force;  // Y (thermodynamic) or the target damage of eq. 23 (Rankine-Mohr-Coulomb)
  Real* bulk = nullptr;   // the displacement form: each elastic particle's moduli (intact where it
  Real* shear = nullptr;  // does not damage), which its pair forces take
  Real* tensile = nullptr;      // Rankine-Mohr-Coulomb: D_t and D_c of eqs. 20 and 22 at this state
  Real* compressive = nullptr;

  PSPH_HD void operator()(int i) const {
    const int mi = s.material[i];
    if (!mats.is_elastic(mi)) return;
    const Real k0 = mats[mi].bulk_modulus, mu0 = mats[mi].shear_modulus;
    if (!law.damages(mi)) {
      if (bulk) bulk[i] = k0, shear[i] = mu0;
      return;
    }
    if (is_retired_ghost(s.ghost, i)) return;  // no neighbours: no strain, no stress, its damage kept
    const Mat<D> eps = s.strain[i];
    DamagedModuli c;
    if (law.rankine) {
      RankineMohrCoulombTarget target;
      damage[i] = rankine_mohr_coulomb_update(law.rmc, damage[i], eps, k0, mu0, &target);
      driving_force[i] = target.combined;
      if (tensile) tensile[i] = target.tensile, compressive[i] = target.compressive;
      c = rankine_mohr_coulomb_moduli(law.degrades, k0, mu0, damage[i]);
      if (s.ghost && is_damage_ghost(law.degrades, law.ghost_threshold, damage[i])) s.ghost[i] = kGhostPending;
    } else {
      const ThermodynamicDamage& m = law.thermo[mi];
      damage[i] = thermodynamic_damage_update(m, damage[i], eps, k0, mu0);
      driving_force[i] = damage_driving_force(m, damage[i], driving_energy(eps, k0, mu0, m.unilateral));
      c = thermodynamic_moduli(m, trace(eps), k0, mu0, damage[i]);
    }
    if (bulk) bulk[i] = c.bulk, shear[i] = c.shear;
    const Mat<D> stress = small_strain_stress(eps, c.bulk, c.shear);
    if (s.piola) {  // large strain: eps is E and stress is S
      LargeStrain<D> ls;
      ls.F = s.defgrad[i];
      piola_and_cauchy(ls, stress);
      s.piola[i] = ls.piola, s.stress[i] = ls.cauchy;
    } else {
      s.stress[i] = stress;
    }
  }
};

// The damage above which a particle counts as damaged (the monitor damaged_particles).
constexpr double kDamaged = 1e-3;

// Per particle: 1 where damage > kDamaged (the count of damaged particles), the damage, and the
// energy its damage dissipated (Deptulski eq. 4.26b, times the particle's volume).
struct DamagedOf {
  const Real* damage;
  PSPH_HD Real operator()(int i) const { return damage[i] > Real(kDamaged) ? Real(1) : Real(0); }
};
struct DamageOf {
  const Real* damage;
  PSPH_HD Real operator()(int i) const { return damage[i]; }
};
template <int D>
struct DamageEnergyOf {
  ParticleView<D> s;
  DamageLaw law;
  const Real* damage;
  PSPH_HD Real operator()(int i) const {
    const int mi = s.material[i];
    if (law.rankine || !law.damages(mi)) return Real(0);
    return s.m[i] / s.rho[i] * dissipated_energy_density(law.thermo[mi], damage[i]);
  }
};

}  // namespace psph
