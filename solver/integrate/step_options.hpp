#pragma once
// How a step advances (the engine's options: integrator, time step, health checks).

namespace psph {

enum class Integrator { Leapfrog, VelocityVerlet };

struct StepOptions {
  Integrator integrator = Integrator::VelocityVerlet;
  double dt_factor = 1;        // scales every time-step limit
  double fixed_dt = 0;         // > 0: constant step instead of the adaptive one
  double min_dt_ratio = 1e-4;  // a step below this fraction of the first step is a collapse
  // |rho/rho0 - 1| of a fluid particle past which the run warns (engine/density_watch.hpp), or
  // stops when `stop_on_density_deviation`.
  double max_density_deviation = 0.03;
  bool stop_on_density_deviation = false;
  // A run over several processes cuts its domain anew when the slowest process's step time passes
  // this multiple of the mean (parallel/); 1: at every list build.
  double rebalance_imbalance = 1.2;
};

}  // namespace psph
