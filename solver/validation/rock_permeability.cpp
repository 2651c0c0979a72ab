#include "validation/rock_permeability.hpp"

#include <cmath>

#include "scene/embedded_cases.hpp"
#include "scene/image_path.hpp"
#include "scene/scene_builder.hpp"
#include "validation/validation_cases.hpp"

namespace psph {
namespace {

constexpr double kVoxel = 5.345e-6;  // m, the case's voxel
constexpr double kCropVoxels = 32;   // along each axis

}  // namespace

toml::table berea_case_table(const std::string& name) {
  std::vector<std::string> tried;
  if (find_image_file("berea_110.raw", "cases/" + name + ".toml", tried).empty())
    throw ValidationUnavailable("no Berea image (berea_110.raw) in ../shared/data/rocks or PORESPH_IMAGE_PATH");
  return toml::parse(embedded_case_text(name), std::string_view("cases/" + name + ".toml"));
}

Case berea_permeability_case(int per_voxel) {
  toml::table tbl = berea_case_table("berea_permeability");
  set_case_spacing(tbl, kVoxel / per_voxel);
  tbl["geometry"].as_array()->at(1).as_table()->insert_or_assign("particles_per_voxel", per_voxel);
  Case c = parse_case(tbl, "cases/berea_permeability.toml");
  build_particles(c);
  return c;
}

Permeability berea_permeability(int per_voxel, const std::string& backend) {
  PermeabilityRun run;
  run.bulk_volume = std::pow(kCropVoxels * kVoxel, 3);  // the crop: the sleeve is not rock
  // The slowest mode of the pores decays in ~ (pore radius)^2 / nu = (8 voxels)^2 / nu = 1.8 ms.
  run.interval = 2e-4, run.min_time = 1e-3, run.max_time = 2e-2, run.change = 2e-3;
  return measure_permeability(berea_permeability_case(per_voxel), backend, run);
}

Richardson richardson(const std::vector<double>& h, const std::vector<double>& K) {
  // (K0 - K1) / (K1 - K2) = (h0^p - h1^p) / (h1^p - h2^p), increasing in p for h0 > h1 > h2.
  const double target = (K[0] - K[1]) / (K[1] - K[2]);
  auto ratio = [&](double p) { return (std::pow(h[0], p) - std::pow(h[1], p)) / (std::pow(h[1], p) - std::pow(h[2], p)); };
  double lo = 0.2, hi = 8;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (ratio(mid) < target ? lo : hi) = mid;
  }
  Richardson r;
  r.order = 0.5 * (lo + hi);
  const double C = (K[1] - K[2]) / (std::pow(h[1], r.order) - std::pow(h[2], r.order));
  r.limit = K[2] - C * std::pow(h[2], r.order);
  return r;
}

}  // namespace psph
