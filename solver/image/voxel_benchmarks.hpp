#pragma once
// Voxel geometries with known flow (flow along z, periodic along z, label 0 pore, 1 solid): what
// the permeability of segmented images is validated on (VALIDATION.md "Flow through voxel
// images"), each also solved by the independent lattice-Boltzmann reference (tests/reference/).
//   duct          a square duct `width` voxels across in a one-voxel solid frame (exact series)
//   twin_ducts    two such ducts side by side, one voxel of solid between them (no flow through it)
//   tilted_slit   a slit `width` voxels across whose walls are staircases: its mid-plane runs along
//                 (2, 1) across a periodic x-y section `size` voxels wide (x and y periodic too)
//   sphere_array  one solid sphere of radius `radius` voxels in a periodic cube of `size`
//   dead_ends     a duct with closed side branches (`width` across, 2 width deep) every 2 width
//   zigzag        a duct that climbs along z, turns along x, climbs, and turns back (four L-bends)
#include <string>

#include "image/claystone_sample.hpp"

namespace psph {

struct VoxelBenchmark {
  std::string kind = "duct";
  long width = 4;      // voxels across the duct or slit
  long length = 6;     // voxels along z (duct, twin_ducts, tilted_slit)
  long size = 32;      // the periodic cell (tilted_slit, sphere_array)
  double radius = 14;  // voxels (sphere_array)
};

// The kinds above, for messages and the command line.
const char* const* voxel_benchmark_kinds();
// Throws std::invalid_argument naming the parameter when the geometry cannot be made.
LabelVolume make_voxel_benchmark(const VoxelBenchmark& spec);

}  // namespace psph
