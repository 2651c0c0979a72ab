#pragma once
// The voxels of some phases that lie deep inside them: farther than `reach` voxels along each axis
// (a box, Chebyshev-like per axis) from any voxel of another phase and from the volume's faces.
// A rigid wall needs particles only within a support radius of what moves; the deep ones are
// dropped (`[[geometry]] wall_depth`, scene/read_image.cpp). The faces count as another phase:
// what lies beyond the image (a reservoir, another geometry) is not known here.
#include <array>

#include "image/phase_volume.hpp"

namespace psph {

// Sets the deep voxels of `phases` (bit p: phase p) to phase `to`; returns how many. `axes`: the
// axes the volume extends along (2 for a 2D slice). 1 byte a voxel while it works.
long replace_deep_voxels(PhaseVolume& v, unsigned phases, const std::array<long, 3>& reach, int axes, std::uint8_t to);

}  // namespace psph
