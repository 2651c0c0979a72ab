#pragma once
// What the decomposition of a real geometry over 2 ... 4,096 processes would exchange, counted by
// the decomposition itself (parallel/decomposition.hpp) without running a step: each process's
// cost share and its halo (the copies of other processes' particles within the halo width).
#include <ostream>
#include <string>
#include <vector>

#include "engine/scene.hpp"

namespace psph {

struct DecompositionCount {
  std::string case_name;
  int processes = 0;
  long long particles = 0;
  double cost_imbalance = 0;   // the largest process's cost over the mean
  double halo_mean = 0, halo_max = 0;  // halo copies per process
  double halo_per_particle = 0;        // all copies over all particles
  double owned_mean = 0;
};

std::vector<DecompositionCount> count_decompositions(const std::string& name, const Scene& sc, double halo_width,
                                                     const std::vector<int>& processes, std::ostream* log);

// The geometries of the issue: SPHERIC test 2 at 6 mm and the published claystone cell.
std::vector<DecompositionCount> decomposition_sweep(const std::vector<int>& processes, std::ostream* log);

}  // namespace psph
