#pragma once
// Rigid-body motion against analytical trajectories (rigid/):
// - a torque-free symmetric top in free fall (cases/rigid_top_3d.toml): centre x0 + v0 t + g t^2/2;
//   orientation R(t) = Rot(L, |L| t / I1) Rot(e3, (1/I3 - 1/I1)(L . e3) t) with L fixed (the axis
//   e3 precesses about L, the body spins about e3); every particle at X(t) + R(t) q.
// - a cylinder settling through a periodic square array (cases/settling_cylinder_2d.toml): its
//   terminal velocity against Sangani & Acrivos (1982).
#include <string>

#include "scene/case_file.hpp"

namespace psph {

// The embedded case `name`; `spacing` > 0 replaces its spacing (sizes and support keep their ratios).
Case rigid_case(const std::string& name, double spacing = 0);

struct TopTrajectory {
  double position_error = 0;   // max over particles and samples of |x - x_exact| / the body's length
  double centre_error = 0;     // max |X - X_exact| / the distance fallen
  double momentum_drift = 0;   // max | |L| / |L0| - 1 |
  double energy_drift = 0;     // max |E_rot / E_rot0 - 1|, E_rot = omega . L / 2
  double precession_turns = 0; // of the axis about L over the run
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};
TopTrajectory run_rigid_top(const Case& c, const std::string& backend);

struct SettlingDrag {
  double solid_fraction = 0;       // the lattice's: body particles / all particles
  double drag = 0;                 // F / ((1 - c) mu U), U the mean velocity over the cell relative to the body
  double drag_reference = 0;       // Sangani & Acrivos' square array at the lattice's solid fraction
  double drag_change = 0;          // relative change over the run's last tenth (steadiness)
  double reynolds = 0;             // rho V a / mu with the body's speed
  double angular_velocity = 0;     // rad/s (0 by symmetry)
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};
SettlingDrag run_settling_cylinder(Case c, const std::string& backend);

// F / (mu U) of a square array of cylinders at solid fraction c: Sangani & Acrivos (1982) eq.
// 4.13 / Hasimoto (1959), 4 pi / (-ln(c)/2 - 0.738 + c - 0.887 c^2 + 2.038 c^3); 0.1 % from
// their Table 1 at c <= 0.1 (24.81 against 24.83 at 0.1), 1.5 % at 0.2.
double sangani_acrivos_square(double c);

}  // namespace psph
