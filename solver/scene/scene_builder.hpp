#pragma once
// Turns a case's geometry into particles: a regular lattice over the domain, each site given the
// material of the last shape that contains it.
#include "scene/case_file.hpp"

namespace psph {

// Fills case.scene's particles. Throws CaseError when the geometry yields no fluid particle.
void build_particles(Case& c);

// sum_j W(x_i - x_j) over an infinite lattice of the given spacing (self included): the number
// density of an interior particle. Masses are rho0 / this, so an interior particle starts at rho0.
double lattice_kernel_sum(int dimension, KernelType kernel, double support, double spacing);

}  // namespace psph
