#pragma once
// Connected components of the pore space of a phase volume (image/phase_volume.hpp): voxels of
// the pore phases joined through their faces (6-connectivity), faces and edges (18) or faces,
// edges and corners (26). Each component's voxels and whether it percolates along each axis
// (touches both of the volume's faces across it). 4 bytes a voxel while labelling.
#include <array>
#include <cstdint>
#include <vector>

#include "image/phase_volume.hpp"

namespace psph {

struct PoreComponent {
  long voxels = 0;
  std::array<bool, 3> percolates{false, false, false};  // along x, y, z
};

struct PoreComponents {
  std::vector<PoreComponent> components;  // the largest first (ties: the first met in x-fastest order)
  std::vector<std::int32_t> label;        // per voxel (x fastest): its component, -1 outside the pore space
};

// `connectivity`: 6, 18 or 26 (ImageError otherwise, naming `file`).
PoreComponents pore_components(const PhaseVolume& v, unsigned pore_phases, int connectivity, const std::string& file);

}  // namespace psph
