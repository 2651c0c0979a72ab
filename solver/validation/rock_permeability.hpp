#pragma once
// Permeability of a crop of a rock image (cases/berea_permeability.toml, cases/ketton_permeability.toml)
// at 1, 2 or 3 particles per voxel, and the Richardson extrapolation of a resolution study.
#include <string>
#include <vector>

#include "validation/permeability.hpp"

namespace psph {

// A shipped permeability case on a cubic crop of a rock image, with its independent answer.
struct RockCrop {
  std::string case_name;      // cases/<case_name>.toml (embedded)
  std::string image;          // the image file it reads
  double voxel = 0;           // m
  double crop_voxels = 0;     // along each axis
  double lattice_boltzmann = 0;  // m^2: tests/reference/voxel_lbm on the same voxels (VALIDATION.md)
  double lattice_boltzmann_limit = 0;  // m^2: its extrapolation through its refinements
  double coarse_excess = 0;   // |K(1 per voxel)/K_LB - 1| measured: the CI tolerance less its margin
  double finest_tolerance = 0.05;  // |K(3 per voxel)/K_LB - 1|
};
const RockCrop& berea_crop();
const RockCrop& ketton_crop();

// The embedded case `name` reading `image` as a table, or ValidationUnavailable where the image
// is missing.
toml::table rock_case_table(const std::string& name, const std::string& image);
inline toml::table berea_case_table(const std::string& name) { return rock_case_table(name, "berea_110.raw"); }

// The case at `per_voxel` particles per voxel (ValidationUnavailable where the image is missing).
Case rock_permeability_case(const RockCrop& rock, int per_voxel);
Permeability rock_permeability(const RockCrop& rock, int per_voxel, const std::string& backend);

struct Richardson {
  double limit = 0, order = 0;  // K(h) = limit + C h^order
};
// From K at spacings h[0] > h[1] > h[2] (any ratios; the order solved by bisection in (0.2, 8)).
Richardson richardson(const std::vector<double>& h, const std::vector<double>& K);

}  // namespace psph
