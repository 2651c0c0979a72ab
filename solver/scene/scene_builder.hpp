#pragma once
// Turns a case's geometry into particles: a regular lattice over the domain, each site given the
// material of the last shape that contains it, and the shells of concentric spheres
// (scene/concentric_layout.hpp), each point kept where that sphere is the last shape containing it.
#include "scene/case_file.hpp"

namespace psph {

// Fills case.scene's particles (a particle standing for volume V weighs rho0 / lattice sum * V /
// dx^D). Throws CaseError when the geometry yields no fluid, elastic or rigid particle.
void build_particles(Case& c);
// The same, only the particles inside `part` (lower <= x < upper on every axis): a share of the
// domain, as a process of a decomposed run will build its own. The checks (every rigid body holds
// particles, the loads take some) then see only that share.
void build_particles(Case& c, const Bounds& part);
Bounds domain_bounds(const Scene& sc);
// The points build_particles would visit: the domain's lattice sites and the points of the shapes
// with their own layout (in double: it may be far beyond what could be built).
double particle_work_estimate(const Case& c);

// A periodic cube of edge `length` filled with one fluid on a lattice of `per_axis` sites per axis,
// support = support_per_spacing spacings (cubic spline), carrying a shear wave
// v_x = amplitude sin(2 pi y / length) (along x in 1D). Benchmarks and engine tests use it.
struct ShearBox {
  int dimension = 3, per_axis = 10;
  double length = 1, support_per_spacing = 2;
  double density = 1000, viscosity = 1e-3, sound_speed = 1, amplitude = 1e-2;
};
Scene shear_box_scene(const ShearBox& b);

// sum_j W(x_i - x_j) over an infinite lattice of the given spacing (self included): the number
// density of an interior particle. Masses are rho0 / this, so an interior particle starts at rho0.
double lattice_kernel_sum(int dimension, KernelType kernel, double support, double spacing);

}  // namespace psph
