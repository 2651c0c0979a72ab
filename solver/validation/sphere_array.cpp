#include "validation/sphere_array.hpp"

#include <cmath>
#include <stdexcept>

#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

namespace psph {

double sphere_array_reference(double phi) {
  if (std::fabs(phi - 0.343) < 1e-6) return 3.1728e-8;
  if (std::fabs(phi - 0.45) < 1e-6) return 1.5904e-8;
  if (std::fabs(phi - 0.5236) < 1e-5) return 1.0107e-8;  // touching: pi/6 = 0.523599
  throw std::invalid_argument("no reference permeability for solid fraction " + std::to_string(phi));
}

Case sphere_array_case(double phi, double support_per_spacing, const std::string& kernel) {
  const std::string text = embedded_case_text("sphere_array");
  toml::table tbl = toml::parse(text, std::string_view("cases/sphere_array.toml"));
  const double L = 2e-3, support = 1e-4;
  const double R = std::cbrt(phi * 3 * L * L * L / (4 * M_PI));  // Pazdniakou eq. 81
  set_case_value(tbl, "discretisation.spacing", toml::value<double>(support / support_per_spacing));
  set_case_value(tbl, "discretisation.kernel", toml::value<std::string>(kernel));
  tbl["geometry"].as_array()->at(1).as_table()->insert_or_assign("radius", R);
  Case c = parse_case(tbl, "cases/sphere_array.toml");
  build_particles(c);
  return c;
}

}  // namespace psph
