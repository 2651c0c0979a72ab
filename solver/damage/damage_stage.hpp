#pragma once
// The damage stage of the elastic solid ([damage]): after the elastic stage's strain pass, each
// damaging particle's damage is updated from its strain and its stress degraded
// (damage/damage_pass.hpp), before the force passes read it. Rankine-Mohr-Coulomb (Pazdniakou
// 2018 §2.2.2) or AT-1, AT-2, PCW (Deptulski 2021 §4.1). Fields `damage` and
// `damage_driving_force`, with Rankine-Mohr-Coulomb `tensile_damage` and `compressive_damage` (the
// parts of eq. 23), and in the displacement form (or with the pair_eos coupling) `damaged_bulk_modulus`
// and `damaged_shear_modulus`, which its pair forces (and the solid's own pressure) read
// (solid/elastic_force.hpp, solid/fluid_coupling.hpp); monitors: damaged
// particles, total damage, energy dissipated by damage. With degraded = "ghost", the particles that
// drop out of every interaction (damage/ghosts.hpp): field `damage_ghost`, monitor
// `ghost_particles`. All are registered fields: checkpoints and reorderings carry them.
#include <vector>

#include "core/pass_profile.hpp"
#include "damage/damage_options.hpp"
#include "damage/damage_parameters.hpp"
#include "damage/damage_pass.hpp"
#include "damage/ghosts.hpp"
#include "solid/elastic_force.hpp"
#include "stage/monitor_value.hpp"
#include "stage/step_context.hpp"

namespace psph {

template <int D, class B>
class DamageStage {
 public:
  bool active() const { return active_; }

  // `pair_moduli`: the solid is in displacement form, or presents its own pressure to a fluid.
  void setup(StepContext<D, B>& cx, const DamageOptions& o, bool pair_moduli) {
    active_ = cx.elastic && o.damage_model != DamageModel::None;
    if (!active_) return;
    law_.rankine = o.damage_model == DamageModel::RankineMohrCoulomb;
    law_.materials = o.damage_materials;
    law_.rmc = rankine_mohr_coulomb_parameters(o);
    law_.degrades = o.damage_degrades;
    law_.ghost_threshold = Real(o.ghost_threshold);
    for (int k = 0; k < cx.mats.count; ++k) law_.thermo[k] = thermodynamic_parameters(o, cx.mats.m[k]);
    const int n = cx.n();
    damage_.resize(n), driving_force_.resize(n);
    damage_.zero(), driving_force_.zero();
    cx.s.add_field(damage_, 1, "damage", "-", "damage D in [0, 1) of the elastic solid ([damage])");
    cx.s.add_field(driving_force_, 1, "damage_driving_force", "Pa",
                   "Y = -g'(D) w~ (AT-1, AT-2, PCW); the target damage of eq. 23 (Rankine-Mohr-Coulomb)");
    if (law_.rankine) {
      tensile_.resize(n), compressive_.resize(n);
      tensile_.zero(), compressive_.zero();
      cx.s.add_field(tensile_, 1, "tensile_damage", "-", "D_t of eq. 20 where eq. 19 holds, at this state (Rankine-Mohr-Coulomb)");
      cx.s.add_field(compressive_, 1, "compressive_damage", "-",
                     "D_c of eq. 22 where eq. 21 holds, at this state (Rankine-Mohr-Coulomb)");
    }
    if (law_.rankine && law_.degrades == DamageDegrades::Ghost) {
      cx.s.ghost.resize(n);
      cx.s.ghost.zero();
      cx.s.add_field(cx.s.ghost, 1, "damage_ghost", "-",
                     "1: a damage ghost, out at the next list build; 2: out of every interaction; 0: neither");
    }
    if (!pair_moduli) return;
    bulk_.resize(n), shear_.resize(n);
    bulk_.zero(), shear_.zero();
    cx.s.add_field(bulk_, 1, "damaged_bulk_modulus", "Pa", "the damaged bulk modulus k(D) (displacement form, pair_eos coupling)");
    cx.s.add_field(shear_, 1, "damaged_shear_modulus", "Pa", "the damaged shear modulus mu(D) (displacement form, pair_eos coupling)");
  }

  // The degraded moduli of the displacement form and the pair_eos coupling (none otherwise).
  ParticleModuli moduli() const {
    return bulk_.size() ? ParticleModuli{bulk_.data(), shear_.data()} : ParticleModuli{};
  }

  // After the strain pass, before the forces.
  void update(StepContext<D, B>& cx) {
    const StageScope scope("damage");
    if (!active_) return;
    cx.launch(DamageUpdatePass<D>{cx.view(), cx.mats, law_, damage_.data(), driving_force_.data(),
                                            bulk_.size() ? bulk_.data() : nullptr, bulk_.size() ? shear_.data() : nullptr,
                                            tensile_.size() ? tensile_.data() : nullptr,
                                            tensile_.size() ? compressive_.data() : nullptr});
  }

  // Ghosts: a list build is due (a particle became a ghost in the last damage pass).
  bool ghosts_pending(StepContext<D, B>& cx) const {
    const StageScope scope("damage");
    return cx.s.ghost.size() && cx.template max_of<int>(PendingGhostOf<D>{cx.view()}) > 0;
  }
  // Before each list build, and after the forces.
  void retire_ghosts(StepContext<D, B>& cx) const {
    const StageScope scope("damage");
    if (cx.s.ghost.size()) cx.launch(RetireGhosts<D>{cx.view()});
  }
  void pin_ghosts(StepContext<D, B>& cx) const {
    const StageScope scope("damage");
    if (cx.s.ghost.size()) cx.launch(PinGhosts<D>{cx.view()});
  }

  void monitors(StepContext<D, B>& cx, std::vector<MonitorValue>& out) const {
    const StageScope scope("damage");
    if (!active_) return;
    if (cx.s.ghost.size()) out.push_back({"ghost_particles", double(cx.template sum_of<Real>(GhostOf<D>{cx.view()})), "-"});
    out.push_back({"damaged_particles", double(cx.template sum_of<Real>(DamagedOf{damage_.data()})), "-"});
    out.push_back({"total_damage", double(cx.template sum_of<Real>(DamageOf{damage_.data()})), "-"});
    if (!law_.rankine)
      out.push_back({"damage_energy", double(cx.template sum_of<Real>(DamageEnergyOf<D>{cx.view(), law_, damage_.data()})), "J"});
  }

 private:
  bool active_ = false;
  DamageLaw law_;
  DeviceArray<Real, B> damage_, driving_force_;
  DeviceArray<Real, B> bulk_, shear_;  // the displacement form, the pair_eos coupling
  DeviceArray<Real, B> tensile_, compressive_;  // Rankine-Mohr-Coulomb only
};

}  // namespace psph
