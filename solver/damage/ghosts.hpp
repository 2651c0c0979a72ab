#pragma once
// Damage ghosts (Pazdniakou 2018 §4.7, Fig. 14d; [damage] degraded = "ghost"): a particle whose
// Rankine-Mohr-Coulomb damage reaches the threshold stops interacting with everything. The damage
// pass marks it pending (damage/damage_pass.hpp); the next list build, which the step requests at
// once, retires it: it leaves every list (neighbours/neighbour_list.hpp) and the large-strain
// solid's lists of t = 0 (neighbours/reference_list.hpp), so that the fluid flows into the space it
// held, and it stays at rest where it dropped out. The solid's volume is not conserved (the paper's
// observation). A ghost is one for good: with no neighbours its strain is zero, so a reversible
// law would heal it at once. The field `damage_ghost` is a registered field: checkpoints carry the
// pending ghosts, and a restart rebuilds the lists as they were.
#include "core/damage_ghost.hpp"
#include "core/material.hpp"
#include "state/particles.hpp"
#include "core/pass_fields.hpp"

namespace psph {

// Before a list build: the pending ghosts retire.
template <int D>
struct RetireGhosts {
  static constexpr FieldNames neighbour_reads{};
  static constexpr FieldNames writes{"damage_ghost"};
  ParticleView<D> s;
  PSPH_HD void operator()(int i) const {
    if (s.ghost[i] == kGhostPending) s.ghost[i] = kGhostRetired;
  }
};

// After the forces (the loads' imposed velocities too): a retired ghost has no velocity and no
// acceleration, so that it stays where it dropped out.
template <int D>
struct PinGhosts {
  static constexpr FieldNames neighbour_reads{};
  static constexpr FieldNames writes{"velocity", "acceleration", "xsph_correction"};
  ParticleView<D> s;
  PSPH_HD void operator()(int i) const {
    if (s.ghost[i] != kGhostRetired) return;
    s.v[i] = Vec<D>::zero(), s.a[i] = Vec<D>::zero(), s.v_xsph[i] = Vec<D>::zero();
  }
};

// 1 for a pending ghost (max over particles: a list build is due), and for any ghost (their count).
template <int D>
struct PendingGhostOf {
  ParticleView<D> s;
  PSPH_HD int operator()(int i) const { return s.ghost[i] == kGhostPending ? 1 : 0; }
};
template <int D>
struct GhostOf {
  ParticleView<D> s;
  PSPH_HD Real operator()(int i) const { return s.ghost[i] != 0 ? Real(1) : Real(0); }
};

}  // namespace psph
