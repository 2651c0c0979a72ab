#pragma once
// Permeability of a crop of the Berea sandstone image (cases/berea_permeability.toml) at 1, 2 or
// 3 particles per voxel, and the Richardson extrapolation of a resolution study of the same crop.
#include <vector>

#include "validation/permeability.hpp"

namespace psph {

// The embedded case `name` (a Berea case) as a table, or ValidationUnavailable where the image
// is missing.
toml::table berea_case_table(const std::string& name);

// The case at `per_voxel` particles per voxel (ValidationUnavailable where the image is missing).
Case berea_permeability_case(int per_voxel);
Permeability berea_permeability(int per_voxel, const std::string& backend);

struct Richardson {
  double limit = 0, order = 0;  // K(h) = limit + C h^order
};
// From K at spacings h[0] > h[1] > h[2] (any ratios; the order solved by bisection in (0.2, 8)).
Richardson richardson(const std::vector<double>& h, const std::vector<double>& K);

}  // namespace psph
