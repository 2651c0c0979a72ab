#pragma once
// An independent reference for poresph's permeabilities: single-phase Stokes flow through a binary
// voxel image by the lattice-Boltzmann method (D3Q19, two-relaxation-time collision with the magic
// parameter 3/16, halfway bounce-back at the voxel faces, periodic box, uniform body force).
// Nothing here shares code with solver/: it is the answer the SPH results are checked against.
#include <cstdint>
#include <functional>
#include <vector>

namespace lbmref {

// A binary image: voxel (x, y, z) is solid[x + nx * (y + ny * z)], 1 = solid, 0 = fluid.
struct Voxels {
  int nx = 0, ny = 0, nz = 0;
  std::vector<std::uint8_t> solid;
};

struct Options {
  int axis = 2;                 // flow (body force) axis: 0 = x, 1 = y, 2 = z
  int refine = 1;               // lattice nodes per voxel edge (each voxel is refine^3 nodes)
  double tolerance = 1e-6;      // stop when <u> changes by less than this, relative, over check_interval,
                                // at two checks in a row (an oscillation seen twice in the same phase is unlikely)
  long max_iterations = 2000000;
  int check_interval = 100;
  // Symmetric relaxation time; viscosity nu = (tau_plus - 1/2) / 3. With Lambda = 3/16 the steady
  // permeability does not depend on it (to ~1e-7), so a large viscosity is chosen: nu = 1 took 2 to 5
  // times fewer iterations than nu = 1/6 or 1/3 on sphere arrays and Berea.
  double tau_plus = 3.5;
  double force = 0;             // body force (lattice units); 0 picks 1e-5 nu / refine^2 (Mach < 0.01)
  std::function<void(long iteration, double permeability, double change)> progress;  // every check
};

struct Result {
  double permeability = 0;      // voxel^2: nu <u_axis> / g over the whole box (solid included)
  long iterations = 0;
  double change = 0;            // relative change of <u> over the last check_interval iterations
  bool converged = false;
  double porosity = 0;          // fluid voxels / all voxels
  long fluid_nodes = 0;
  double seconds = 0;
  double mlups = 0;             // million fluid-node updates per second
  double max_mach = 0;          // max |u| / c_s at the end
  double nu = 0, force = 0;     // lattice units
};

Result solve(const Voxels& voxels, const Options& options);

}  // namespace lbmref
