#include "validation/voxel_references.hpp"

#include <cmath>

namespace psph {
namespace {

VoxelBenchmark shape(const std::string& kind, long width, long size = 32) {
  VoxelBenchmark b;
  b.kind = kind, b.width = width, b.length = 6, b.size = size;
  return b;
}

// A periodic cube of n voxels at solid fraction phi (the radius that gives it exactly); `width`
// is the pore's scale, for the run's time to steady state.
VoxelBenchmark spheres(long n, double phi) {
  VoxelBenchmark b;
  b.kind = "sphere_array", b.size = n, b.width = n / 2, b.radius = n * std::cbrt(3 * phi / (4 * M_PI));
  return b;
}

}  // namespace

// Tolerances: the square ducts' error depends on the particles across them, w x per voxel (2: 6 %,
// 4: 4 %, 8: 1.6 %, 16: 0.4 %, measured). Where the solid has convex corners (staircases, bends,
// branch openings) SPH over-predicts at one and two particles per voxel (measured at c = 1 m/s: the
// slit +37 / +13 %, the bends +27 / +7.8 %): the CI tolerances hold those measured errors with a
// margin, so that they catch a regression; --full asks the 5 % of the issue at 4 per voxel (3 per
// voxel: the measured error with a margin where it is past 5 %: the touching spheres +7.4 %).
const std::vector<VoxelReference>& voxel_references() {
  static const std::vector<VoxelReference> refs = {
      {"square duct 2 voxels", shape("duct", 2), 0.035274223, true, 4, {0.1, 0.05, 0.03, 0.02}},
      {"square duct 3 voxels", shape("duct", 3), 0.114056425, true, 4, {0.05, 0.03, 0.02, 0.02}},
      {"square duct 4 voxels", shape("duct", 4), 0.250148978, true, 4, {0.05, 0.02, 0.02, 0.02}},
      {"square duct 8 voxels", shape("duct", 8), 1.43984645, true, 4, {0.02, 0.02, 0.02, 0.02}},
      {"two ducts 4 voxels, one voxel apart", shape("twin_ducts", 4), 0.272889794, true, 4, {0.1, 0.02, 0.02, 0.02}},
      {"tilted slit 3 voxels", shape("tilted_slit", 3, 20), 0.132886191, false, 4, {0.4, 0.15, 0.1, 0.05}},
      {"sphere array 0.343, 16 voxels", spheres(16, 0.343), 1.7728337, false, 4, {0.26, 0.12, 0.06, 0.05}},
      {"sphere array touching, 16 voxels", spheres(16, M_PI / 6), 0.461244974, false, 4, {0.38, 0.17, 0.09, 0.05}},
      {"duct 3 voxels with dead ends", shape("dead_ends", 3), 0.0573308108, false, 4, {0.22, 0.09, 0.05, 0.05}},
      {"zigzag duct 3 voxels", shape("zigzag", 3), 0.0310411707, false, 4, {0.31, 0.1, 0.06, 0.05}},
  };
  return refs;
}

}  // namespace psph
