#pragma once
// A particle's share of a step's cost, which the decomposition balances (parallel/): by class, as
// the passes treat them. A wall far from the fluid has no lists and no pass work; one near it
// presents a pressure and velocity to the fluid; a solid adds its stress and corrections. A shared
// run measures each class's cost in its initial state (parallel/cost_calibration.hpp); until then,
// and where nothing runs (the decomposition counts of `poresph bench --decomposition`), the static
// guesses below.
#include <cstdint>

#include "core/material.hpp"

namespace psph {

enum CostClass : std::uint8_t { kFluidCost = 0, kSolidCost, kRigidCost, kWallNearFluidCost, kWallFarCost, kCostClasses };

inline const char* cost_class_name(int c) {
  static const char* names[kCostClasses] = {"fluid", "elastic solid", "rigid", "wall near fluid", "wall far from fluid"};
  return names[c];
}

inline CostClass cost_class(MaterialKind kind, bool near_fluid) {
  switch (kind) {
    case MaterialKind::Fluid: return kFluidCost;
    case MaterialKind::Elastic: return kSolidCost;
    case MaterialKind::Rigid: return kRigidCost;
    case MaterialKind::Wall: break;
  }
  return near_fluid ? kWallNearFluidCost : kWallFarCost;
}

// Seconds per particle and force evaluation, or static weights (a fluid particle 1), one per class.
struct ClassCosts {
  double per_particle[kCostClasses] = {1.0, 1.0, 1.0, 0.25, 0.25};
  bool measured = false;
};

// The static weight of a particle of this kind (walls near and far alike).
inline double particle_cost(MaterialKind kind) { return ClassCosts{}.per_particle[cost_class(kind, true)]; }

}  // namespace psph
