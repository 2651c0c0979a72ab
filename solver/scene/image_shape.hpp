#pragma once
// A segmented image in the domain (`[[geometry]] shape = "image"`, scene/read_image.cpp): its
// coarse phases on a grid of voxels from `origin`, and one shape per material holding the lattice
// sites whose voxel has one of that material's phases, or, for a rigid material, one shape per
// connected inclusion (each a rigid body). A 2D case takes the image's slice `slice` along z.
#include <memory>

#include "image/phase_volume.hpp"
#include "scene/shape.hpp"

namespace psph {

struct ImageGrid {
  PhaseVolume volume;
  std::array<double, 3> origin{0, 0, 0}, voxel{1, 1, 1};  // m: the lower corner, a coarse voxel's sides
  int dimension = 3;
  long slice = 0;  // 2D: the voxel layer along z
  std::vector<std::int32_t> inclusion;  // per coarse voxel: its rigid inclusion, -1 none (empty without rigid labels)
};

std::shared_ptr<const Shape> make_image_phases(std::shared_ptr<const ImageGrid> grid, unsigned phases);
// The voxels of inclusion `index` (ImageGrid::inclusion), within the box [lower, upper] of voxels.
std::shared_ptr<const Shape> make_image_inclusion(std::shared_ptr<const ImageGrid> grid, std::int32_t index,
                                                  const std::array<long, 3>& lower, const std::array<long, 3>& upper);

}  // namespace psph
