#pragma once
// Permeability of voxel geometries with known flow (image/voxel_benchmarks.hpp) at a number of
// particles per voxel, against the exact answer where there is one and the lattice-Boltzmann
// reference (tests/reference/voxel_lbm) on the same voxels.
#include <string>

#include "image/voxel_benchmarks.hpp"
#include "validation/permeability.hpp"

namespace psph {

struct VoxelPermeability {
  Permeability run;
  double K_voxels = 0;  // K / voxel^2, over the image's box
};

// Writes the geometry to a temporary NumPy file, builds the case around it (an image inside a
// rock sleeve one support radius thick along a closed axis; periodic along z and along the
// geometry's periodic axes), drives water along z to steady state.
VoxelPermeability voxel_permeability(const VoxelBenchmark& geometry, int per_voxel, const std::string& backend);

// The exact K / voxel^2 of the ideal geometry (square ducts: the series solution; the tilted slit:
// plane Poiseuille over its aperture; sphere arrays: Sangani & Acrivos / Zick & Homsy); 0 when
// there is none (dead ends, zigzag).
double voxel_exact_permeability(const VoxelBenchmark& geometry);

}  // namespace psph
