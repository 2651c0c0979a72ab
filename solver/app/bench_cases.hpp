#pragma once
// Benchmark scenes: a periodic box of fluid with a shear-wave velocity field (every particle has a
// full neighbourhood and moves), in 2D and 3D, over a range of sizes.
#include <ostream>
#include <functional>
#include <string>
#include <vector>

#include "core/pass_profile.hpp"
#include "scene/case_file.hpp"

namespace psph {

struct BenchSpec {
  std::string name;
  std::string embedded_case;  // non-empty: time this case file instead of the fluid box
  std::function<Case()> build;  // set: time the case it builds
  int dimension = 3;
  long target_particles = 10000;
  double support_per_spacing = 2.0;  // Pazdniakou's resolution: support = 2 spacings
  int steps = 20;
};

struct BenchResult {
  std::string name, backend, device, precision;
  int dimension = 0, particles = 0, fluid_particles = 0, moving_particles = 0, threads = 1;  // moving: fluid and elastic
  long steps = 0;
  double seconds = 0, particle_steps_per_second = 0, fluid_particle_steps_per_second = 0, neighbours = 0,
         interactions_per_second = 0;
  PassProfile profile;  // the timed steps' passes (core/pass_profile.hpp)
};

// The published drainage cell (Pazdniakou & Dymitrowska 2018 §5.2): ~1.6 M particles, "more than 3
// million time steps", 30 days on a Quadro K5200. Its wall time at a measured rate of the coupled
// step (the claystone_drainage benchmark's particle-steps per second), in hours.
constexpr double kPublishedCellParticles = 1.6e6, kPublishedCellSteps = 3e6;
double published_cell_hours(double particle_steps_per_second);

// SPHERIC test 2 at `spacing` (app/bench_spheric.cpp).
Case spheric_dam_break_case(double spacing);

std::vector<BenchSpec> bench_specs(const std::string& backend, bool quick);
BenchResult run_bench(const BenchSpec& spec, const std::string& backend, std::ostream* log);

}  // namespace psph
