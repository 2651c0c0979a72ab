#pragma once
// A seeded synthetic claystone-like sample (no clay FIB-SEM volume is public): a cube of voxels
// with one fracture-like pore that percolates along z, wide at the top face (the gas entry) and
// narrow at the bottom (the outlet), lens-shaped across (sharp tips, where damage starts), small
// disconnected flat pores around it, and mineral grains (rigid inclusions) in the clay matrix.
// After Deptulski 2021 §5.2 (a 50 h sub-sample, one percolating pore with disconnected pores
// around it, porosity 0.128) and §5.5 (two disconnected pores whose tips point to different sides:
// the fracture's upper part closed to a tip, and its reflection through the centre).
// Labels: 0 pore, 1 clay matrix, 2 mineral grain.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace psph {

struct ClaystoneSpec {
  long size = 50;            // voxels along each axis (one voxel: one coarse voxel of size h)
  std::uint64_t seed = 1;
  double porosity = 0.128;   // the whole pore space (the fracture and the small pores)
  double grains = 0.08;      // volume fraction of mineral grains
  bool two_pores = false;    // Deptulski §5.5's variant
};

// A volume of labels: x fastest, then y, then z.
struct LabelVolume {
  std::array<long, 3> size{0, 0, 0};
  std::vector<std::uint8_t> label;
};
using ClaystoneSample = LabelVolume;  // z = size - 1: the top

ClaystoneSample make_claystone(const ClaystoneSpec& spec);

// A uint8 NumPy file (Fortran order: x fastest, shape (nx, ny, nz)); whole or not at all.
void write_npy(const std::string& file, const LabelVolume& s);

}  // namespace psph
