#pragma once
// A segmented image in the domain (`[[geometry]] shape = "image"`, scene/read_image.cpp): its
// coarse phases on a grid of voxels from `origin`, and one shape per material holding the lattice
// sites whose voxel has one of that material's phases. A 2D case takes the image's slice `slice`
// along z.
#include <memory>

#include "image/phase_volume.hpp"
#include "scene/shape.hpp"

namespace psph {

struct ImageGrid {
  PhaseVolume volume;
  std::array<double, 3> origin{0, 0, 0}, voxel{1, 1, 1};  // m: the lower corner, a coarse voxel's sides
  int dimension = 3;
  long slice = 0;  // 2D: the voxel layer along z
};

std::shared_ptr<const Shape> make_image_phases(std::shared_ptr<const ImageGrid> grid, unsigned phases);

}  // namespace psph
